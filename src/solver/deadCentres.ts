/**
 * Dead centres of a crank-rocker: the two poses where crank and coupler are collinear, so the rocker
 * stops and turns back. Extended: theta3 = theta2, B at distance r2 + r3 from O2. Folded:
 * theta3 = theta2 + pi, B at r3 - r2 from O2. In both, B also lies at r4 from O4, so each dead centre
 * is the triangle O2 O4 B with sides r1, d, r4 (d = r2 + r3 or r3 - r2), solved with the exact
 * half-angle form of triangle.ts. The rocker's swing and the crank's quick-return angle are
 * differences of two such angles; where they are small they are taken from cancellation-free
 * identities instead of subtracting (a crank 1e-6 of the ground swings the rocker by ~1e-6 rad).
 */
import { PI } from './angles';
import { sumOfProducts } from './exact';
import { triangleAngle } from './triangle';
import type { TriangleAngle } from './triangle';
import type { Linkage } from './types';
import { normalizeLinkage } from './validate';

/** A dead-centre pose: input angle and rocker angle in radians, wrapped to (-pi, pi]. */
export interface DeadCentre {
  theta2: number;
  theta4: number;
}

/** Dead centres, rocker swing (rad, in [0, pi]) and quick-return time ratio (>= 1) of a crank-rocker. */
export interface CrankRockerStroke {
  extended: DeadCentre;
  folded: DeadCentre;
  swing: number;
  timeRatio: number;
}

/** An angle already in [-pi, pi], with -pi reported as pi and -0 as 0. */
function halfOpen(x: number): number {
  if (x === -PI) return PI;
  return x === 0 ? 0 : x;
}

/** sin((x + y) / 2) for x, y in [0, pi], from whichever of (x + y) / 2 and its supplement is accurate. */
function sinHalfSum(x: TriangleAngle, y: TriangleAngle): number {
  const half = (x.angle + y.angle) / 2;
  // Near pi the sum's rounding would swamp a small sine; the supplements carry it exactly.
  return half <= PI / 2 ? Math.sin(half) : Math.sin((x.supplement + y.supplement) / 2);
}

/**
 * A difference x - y of two angles in [0, pi] whose half-difference sine is known accurately as
 * sinHalf: 2 asin(sinHalf) where asin is well conditioned (|x - y| <= pi / 2), else the plain
 * difference, which no longer cancels badly there.
 */
function accurateDifference(x: number, y: number, sinHalf: number): number {
  const direct = x - y;
  if (Math.abs(direct) > PI / 2 || !Number.isFinite(sinHalf)) return direct;
  return 2 * Math.asin(Math.max(-1, Math.min(1, sinHalf)));
}

/**
 * Whether the input is a crank driving a rocking output: it turns fully (inputTurnsFully, from
 * inputRange) and is the strictly shortest link, so it is a Grashof crank-rocker (I-2) or its
 * change-point limit (III-2). A double crank, a parallelogram or a kite (shortest link shared) is not.
 * In III-2 one dead centre is the flat pose where the branches cross: the rocker turns back there at a
 * corner of the branch (its velocity changes sign) rather than with w4 = 0.
 */
export function isCrankRocker(l: Linkage, inputTurnsFully: boolean): boolean {
  return inputTurnsFully && l.r2 < l.r1 && l.r2 < l.r3 && l.r2 < l.r4;
}

/**
 * Dead centres of a crank-rocker on branch sigma (+1 open, -1 crossed), the rocker's swing and the
 * time ratio. The caller checks isCrankRocker first; l must be a valid linkage.
 * On the open branch B lies above the ground line at both dead centres (sin(theta4 - theta3) > 0 with
 * theta3 along O2 B), so theta2 = alpha (extended) and alpha - pi (folded), theta4 = pi - beta, where
 * alpha and beta are the triangle's angles at O2 and O4; the crossed branch is the mirror image.
 */
export function crankRockerStroke(l: Linkage, sigma: number): CrankRockerStroke {
  const { r1, r2, r3, r4 } = normalizeLinkage(l);
  const dExtended = [r2, r3];
  const dFolded = [r3, -r2];
  const alphaE = triangleAngle([r1], dExtended, [r4]);
  const alphaF = triangleAngle([r1], dFolded, [r4]);
  const betaE = triangleAngle([r1], [r4], dExtended);
  const betaF = triangleAngle([r1], [r4], dFolded);

  // cos(alphaE) - cos(alphaF) = -r2 G / (r1 (r3^2 - r2^2)) with G = r1^2 + r2^2 - r3^2 - r4^2 (law of
  // cosines in both triangles), and = -2 sin((alphaE + alphaF) / 2) sin(delta / 2): delta = alphaE - alphaF
  // is then as accurate as G, summed in double-double from exact squares. delta = 0 iff G = 0 (no quick return).
  const g = sumOfProducts([
    [r1, r1],
    [r2, r2],
    [-r3, r3],
    [-r4, r4],
  ]);
  const sinHalfDelta = (r2 * (g.hi + g.lo)) / (2 * r1 * (r3 - r2) * (r3 + r2) * sinHalfSum(alphaE, alphaF));
  const delta = accurateDifference(alphaE.angle, alphaF.angle, sinHalfDelta);
  // cos(betaF) - cos(betaE) = ((r2 + r3)^2 - (r3 - r2)^2) / (2 r1 r4) = 2 r2 r3 / (r1 r4) exactly.
  const sinHalfSwing = (r2 * r3) / (r1 * r4 * sinHalfSum(betaE, betaF));
  const swing = Math.abs(accurateDifference(betaE.angle, betaF.angle, sinHalfSwing));
  // The crank turns pi + |delta| one way between the dead centres and pi - |delta| the other way.
  const d = Math.abs(delta);
  const timeRatio = 1 + (2 * d) / (PI - d);
  return {
    extended: { theta2: halfOpen(sigma * alphaE.angle), theta4: halfOpen(sigma * betaE.supplement) },
    folded: { theta2: halfOpen(-sigma * alphaF.supplement), theta4: halfOpen(sigma * betaF.supplement) },
    swing,
    timeRatio,
  };
}
