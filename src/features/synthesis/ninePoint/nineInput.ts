import type { Point } from '../../../solver/kinematics';
import { formatNumber } from '../../../shared/format';
import { ninePointRefusal } from '../../../synthesis/ninePoint/ninePointSynthesis';
import type { NinePointMessages } from './ninePointMessages';

/** Why the targets cannot be solved, as a sentence naming the points, or null when they can. */
export function nineRefusalText(targets: readonly Point[], nt: NinePointMessages): string | null {
  if (targets.length !== 9) return nt.needNine(targets.length);
  const r = ninePointRefusal(targets);
  if (!r) return null;
  if (r.kind === 'coincide')
    return nt.refusalCoincide(r.i + 1, r.j + 1, formatNumber(r.point.x), formatNumber(r.point.y));
  return r.kind === 'line' ? nt.refusalLine : nt.refusalCircle;
}
