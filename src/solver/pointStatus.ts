import type { PointStatus } from './types';

/** Point statuses by code: SweepResult.statusCodes[i] indexes this list (0 ok, 1 unreachable, 2 singular, 3 failed). */
export const POINT_STATUSES: readonly PointStatus[] = ['ok', 'unreachable', 'singular', 'failed'];

/** Status code of a point that closed the loop. */
export const OK = 0;
/** Status code of a point where the loop cannot close. */
export const UNREACHABLE = 1;
/** Status code of a point with no unique pose (a continuum) or a singular NR start. */
export const SINGULAR = 2;
/** Status code of a point the method did not solve. */
export const FAILED = 3;
