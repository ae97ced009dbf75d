import type { PointStatus } from './types';

/** Point statuses by code: SweepResult.statusCodes[i] indexes this list (0 ok, 1 unreachable, 2 singular, 3 failed). */
export const POINT_STATUSES: readonly PointStatus[] = ['ok', 'unreachable', 'singular', 'failed'];

/** The code of each status (its index in POINT_STATUSES). */
export const STATUS_CODE = { ok: 0, unreachable: 1, singular: 2, failed: 3 } as const;
