import type { PointStatus } from '../solver/types';

/** Point statuses by code: a cycle sends one byte per point (a transferable Uint8Array), not thousands of strings. */
export const POINT_STATUSES: readonly PointStatus[] = ['ok', 'unreachable', 'singular', 'failed'];

/** Codes of the statuses (index into POINT_STATUSES). */
export function encodeStatuses(status: readonly PointStatus[]): Uint8Array {
  const out = new Uint8Array(status.length);
  for (let i = 0; i < status.length; i++) {
    const k = POINT_STATUSES.indexOf(status[i]);
    out[i] = k < 0 ? 3 : k;
  }
  return out;
}

/** Statuses from their codes; an unknown code reads as 'failed'. */
export function decodeStatuses(codes: ArrayLike<number>): PointStatus[] {
  const out = new Array<PointStatus>(codes.length);
  for (let i = 0; i < codes.length; i++) out[i] = POINT_STATUSES[codes[i]] ?? 'failed';
  return out;
}
