// The solver's modules themselves, not its barrel: the barrel would pull the sweep and NR into the main bundle.
import { degToRad } from '../../solver/angles';
import { solveClosedForm } from '../../solver/closedForm';
import { transmissionAngle } from '../../solver/kinematics';
import type { Branch, Linkage } from '../../solver/types';
import type { CouplerPoint } from '../state/appState';
import type { MethodChoice, PointResponse, PoseAngles, SolvedPose } from '../solution';

/** A pose solved on the main thread for the frame being drawn (the ghost only when it is drawn). */
export type LocalPose = SolvedPose;

function anglesAt(l: Linkage, theta2Rad: number, branch: Branch): PoseAngles | null {
  const a = solveClosedForm(l, theta2Rad, branch);
  if (!a) return null;
  return { theta2: theta2Rad, theta3: a.theta3, theta4: a.theta4, mu: transmissionAngle(a) };
}

/**
 * The closed-form pose at theta2Deg on branch (and on the other branch when withGhost), the same formulas
 * the worker uses: under a microsecond, so every animation frame and every drag step gets its own pose.
 * A linkage the solver refuses (not four positive finite lengths) gives no pose rather than a throw.
 */
export function localPose(
  linkage: Linkage,
  theta2Deg: number,
  branch: Branch,
  coupler: CouplerPoint,
  withGhost: boolean,
): LocalPose {
  const theta2Rad = degToRad(theta2Deg);
  const other: Branch = branch === 'open' ? 'crossed' : 'open';
  let pose: PoseAngles | null = null;
  let ghost: PoseAngles | null = null;
  try {
    pose = anglesAt(linkage, theta2Rad, branch);
    ghost = withGhost ? anglesAt(linkage, theta2Rad, other) : null;
  } catch {
    pose = null;
    ghost = null;
  }
  return {
    linkage,
    coupler: { distance: coupler.distance, angleRad: degToRad(coupler.angleDeg) },
    theta2Rad,
    branch,
    pose,
    ghost,
  };
}

/**
 * The local pose in the shape of a point answer without NR runs, for views that mark the pose (the plots'
 * marker): they follow every frame instead of the worker's round trip.
 */
export function poseAsPoint(p: LocalPose, solver: MethodChoice): PointResponse {
  return {
    linkage: p.linkage,
    coupler: p.coupler,
    theta2Rad: p.theta2Rad,
    branch: p.branch,
    pose: p.pose,
    ghost: p.ghost,
    continuation: null,
    cold: null,
    solver,
    work: { points: p.ghost ? 2 : 1, iterations: 0 },
  };
}
