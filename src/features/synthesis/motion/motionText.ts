import type { MotionMessages } from './motionMessages';
import type { MotionProblem } from './motionSolve';
import { formatNumber } from '../../../shared/format';

/** A Motion problem in words, in the page's language. */
export function problemText(mt: MotionMessages, p: MotionProblem): string {
  switch (p.code) {
    case 'collinear':
      return mt.problems.collinear(mt.pivotName[p.pivot]);
    case 'noCrankPivot':
      return mt.problems.noCrankPivot(formatNumber(p.ground, 4), formatNumber(p.rocker, 4));
    case 'fewDyads':
      return mt.problems.fewDyads(p.found);
    case 'pickTwo':
      return mt.problems.pickTwo(p.picked);
    default:
      return mt.problems[p.code];
  }
}
