/**
 * Roberts–Chebyshev cognates: the two other four-bars whose coupler point traces the same curve as a given one
 * (Roberts 1875, Chebyshev 1878; Norton, "Design of Machinery", §3.8 and the Cayley diagram).
 *
 * In complex numbers, with the coupler point P = A + z (B − A) where z = (pDist / r3) e^{i pAngle}, the loop
 * P = O_A + (A − O_A) + z (B − A) regroups two more ways (O_C = O_A + z (O_B − O_A) is the third fixed pivot):
 *
 *   cognate 1: P = O_A + z (B − A) + (A − O_A)                      pins A1 = O_A + z (B − A), C1 = O_C + z (B − O_B)
 *   cognate 2: P = O_B + (z − 1)(B − A) + (B − O_B)                  pins B2 = O_B + (z − 1)(B − A), C2 = O_C + (1 − z)(A − O_A)
 *
 * and P = O_C + z (B − O_B) + (1 − z)(A − O_A) ties each to O_C, so every vector above turns with θ2, θ3 or θ4
 * of the original and each cognate is a rigid four-bar. Cognate 1's links are |z| (r1, r3, r2, r4) and cognate 2's
 * |1 − z| (r1, r3, r4, r2) (ground, the two moving links from its pivots, coupler), as Roberts' law says.
 */
import { classify } from '../solver';
import type { Point } from '../solver';
import { fourBarFromJoints, placedJoints } from './placed';
import { checkPlaced } from './placed';
import type { PlacedFourBar } from './types';
import { checkFiniteNumber } from './validate';

/** One cognate: the design (its driver chosen as below) and its θ2 at the pose where it was built (radians). */
export interface RobertsCognate {
  design: PlacedFourBar;
  theta2: number;
}

type C = Point;
const add = (a: C, b: C): C => ({ x: a.x + b.x, y: a.y + b.y });
const sub = (a: C, b: C): C => ({ x: a.x - b.x, y: a.y - b.y });
const mul = (a: C, b: C): C => ({ x: a.x * b.x - a.y * b.y, y: a.x * b.y + a.y * b.x });

/** The first θ2 (radians) where the design assembles: 0, else the middle of its first reachable interval. */
function assemblingTheta2(d: PlacedFourBar): number {
  if (placedJoints(d, 0)) return 0;
  const range = classify(d.links).inputRange;
  const iv = range.intervals[0];
  if (!iv) throw new Error(`design cannot be assembled at any input angle: links ${JSON.stringify(d.links)}`);
  return (iv.lo + iv.hi) / 2;
}

/**
 * The cognate made of pivots (p, q) and pins (a on p's link, b on q's link), driven from whichever pivot makes
 * its input a crank (the first given on a tie), with its branch read from this pose.
 */
function cognateOf(pivot1: C, pin1: C, pin2: C, pivot2: C, P: C): RobertsCognate {
  const one = fourBarFromJoints({ O2: pivot1, A: pin1, B: pin2, O4: pivot2, P });
  if (classify(one.design.links).inputIsCrank) return one;
  const two = fourBarFromJoints({ O2: pivot2, A: pin2, B: pin1, O4: pivot1, P });
  return classify(two.design.links).inputIsCrank ? two : one;
}

/**
 * The two Roberts cognates of a placed four-bar: the four-bars, with the same coupler point P, whose P traces the
 * same coupler curve. Each is built at the design's pose at theta2 (radians; default 0, or the middle of its first
 * reachable interval when it cannot assemble at 0) and driven from the pivot that makes its input a crank when
 * one does. Cognate 1 shares the crank pivot O2, cognate 2 the rocker pivot O4. Throws for a design that is not
 * a placed four-bar, one that cannot assemble at theta2, or a coupler point on the line AB's ends (P = A or P = B
 * gives a cognate with a zero link).
 */
export function robertsCognates(design: PlacedFourBar, theta2?: number): [RobertsCognate, RobertsCognate] {
  checkPlaced('design', design);
  const t = theta2 ?? assemblingTheta2(design);
  checkFiniteNumber('theta2', t, 'angle in radians');
  const j = placedJoints(design, t);
  if (!j) throw new Error(`design cannot be assembled at theta2 = ${t} rad`);
  const { O2: OA, A, B, O4: OB, P } = j;
  const z: C = {
    x: (design.pDist / design.links.r3) * Math.cos(design.pAngle),
    y: (design.pDist / design.links.r3) * Math.sin(design.pAngle),
  };
  const oneMinusZ: C = { x: 1 - z.x, y: -z.y };
  const OC = add(OA, mul(z, sub(OB, OA)));
  const A1 = add(OA, mul(z, sub(B, A)));
  const C1 = add(OC, mul(z, sub(B, OB)));
  const B2 = add(OB, mul({ x: z.x - 1, y: z.y }, sub(B, A)));
  const C2 = add(OC, mul(oneMinusZ, sub(A, OA)));
  return [cognateOf(OA, A1, C1, OC, P), cognateOf(OC, C2, B2, OB, P)];
}
