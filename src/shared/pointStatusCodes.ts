// The solver's own list and codes (the module itself, not the barrel: it would pull the sweep into the main bundle).
import { POINT_STATUSES, STATUS_CODE } from '../solver/pointStatus';
import type { PointStatus } from '../solver/types';

/**
 * Codes of the statuses (the solver's POINT_STATUSES order, as SweepResult.statusCodes): a cycle sends one byte per
 * point (a transferable Uint8Array), not thousands of strings. An unknown status is coded as 'failed'.
 */
export function encodeStatuses(status: readonly PointStatus[]): Uint8Array {
  const out = new Uint8Array(status.length);
  for (let i = 0; i < status.length; i++) out[i] = STATUS_CODE[status[i]] ?? STATUS_CODE.failed;
  return out;
}

/** Statuses from their codes (POINT_STATUSES order); an unknown code reads as 'failed'. */
export function decodeStatuses(codes: ArrayLike<number>): PointStatus[] {
  const out = new Array<PointStatus>(codes.length);
  for (let i = 0; i < codes.length; i++) out[i] = POINT_STATUSES[codes[i]] ?? 'failed';
  return out;
}
