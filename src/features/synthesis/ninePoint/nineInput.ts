import type { Point } from '../../../solver/kinematics';
import { formatNumber } from '../../../shared/format';
import { ninePointRefusal } from '../../../synthesis/ninePoint/ninePointSynthesis';
import type { NinePointMessages } from './ninePointMessages';

/** Problem 3 of Wampler, Morgan and Sommese (1992): 64 real linkage classes pass through these nine points. */
export const WMS_PROBLEM_3: Point[] = [
  [0.25, 0.0],
  [0.52, 0.1],
  [0.8, 0.7],
  [1.2, 1.0],
  [1.4, 1.3],
  [1.1, 1.48],
  [0.7, 1.4],
  [0.2, 1.0],
  [0.02, 0.4],
].map(([x, y]) => ({ x, y }));

/** Why the targets cannot be solved, as a sentence naming the points, or null when they can. */
export function nineRefusalText(targets: readonly Point[], nt: NinePointMessages): string | null {
  if (targets.length !== 9) return nt.needNine(targets.length);
  const r = ninePointRefusal(targets);
  if (!r) return null;
  if (r.kind === 'coincide')
    return nt.refusalCoincide(r.i + 1, r.j + 1, formatNumber(r.point.x), formatNumber(r.point.y));
  return r.kind === 'line' ? nt.refusalLine : nt.refusalCircle;
}
