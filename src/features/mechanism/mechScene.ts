import type { MechanismSpec, MechanismSweep } from '../../mechanism';
import type { InputGrid } from './mechAnalysis';
import { valueAt } from './mechAnalysis';
import type { MechArrow, MechPicture, MechTrace } from './drawMechanism';
import { drawnPose, poseAt } from './mechPose';
import type { MechPose } from './mechPose';

/** A vector series on the input grid at a joint or tracer: velocities (length per unit input rate) or reactions (N). */
export interface MechSeriesAt {
  id: string;
  x: ArrayLike<number>;
  y: ArrayLike<number>;
}

/**
 * What the mechanism's canvas draws at any input, but the input and a drag's spec: the page builds it when the
 * linkage, its cycle or the choices change, and both the page and the live stage's worker draw its pictures
 * (mechPictureAt). Plain data, so it crosses to the worker by structured clone.
 */
export interface MechScene {
  /** The analysed linkage. */
  spec: MechanismSpec;
  /** The grid and the positions swept on it; null when the linkage does not run (it is drawn as drawn). */
  grid: InputGrid | null;
  sweep: MechanismSweep | null;
  traces: MechTrace[];
  /** Each slider's slide range over the run (for the guides' lengths). */
  slideRange: Record<string, [number, number]>;
  selected: string | null;
  /** Velocity arrows' series (none when the arrows are off or a joint is dragged). */
  velocities: MechSeriesAt[];
  /** Reaction arrows' series, at joints (none when off or a joint is dragged). */
  forces: MechSeriesAt[];
  /** The linkage cannot move as it is: drawn faint. */
  faint: boolean;
}

/** The arrows of series at the pose's points, their values at input t (a point missing from the pose has none). */
function arrowsAt(scene: MechScene, series: MechSeriesAt[], pose: MechPose, t: number): MechArrow[] {
  const out: MechArrow[] = [];
  for (const s of series) {
    const at = pose.joints[s.id] ?? pose.points[s.id];
    if (at) out.push({ at, vx: valueAt(scene, s.x, t), vy: valueAt(scene, s.y, t) });
  }
  return out;
}

/**
 * The picture of a scene at input t (rad for a pin input, length for a slider), or of the spec a joint's drag draws
 * now (dragged: as drawn, no arrows). Off the grid or not assembled at t, the linkage as drawn.
 */
export function mechPictureAt(scene: MechScene, t: number, dragged: MechanismSpec | null = null): MechPicture {
  const { spec, grid, sweep } = scene;
  if (dragged) {
    const pose = drawnPose(dragged);
    return { ...pictureBase(scene), spec: dragged, pose, arrows: [], forceArrows: [] };
  }
  const pose = (grid && sweep && poseAt(spec, grid, sweep, t)) || drawnPose(spec);
  return {
    ...pictureBase(scene),
    spec,
    pose,
    arrows: arrowsAt(scene, scene.velocities, pose, t),
    forceArrows: arrowsAt(scene, scene.forces, pose, t),
  };
}

function pictureBase(scene: MechScene) {
  return { traces: scene.traces, slideRange: scene.slideRange, selected: scene.selected, faint: scene.faint };
}

/**
 * A short fingerprint of a picture's pose (the sum of x + √2·y over its points, 6 digits): tools and the bench see a
 * new pose drawn. The irrational weight keeps a move along a rational slope (a drag 2 px across, 1 px down) from
 * cancelling out.
 */
export function poseDigest(picture: Pick<MechPicture, 'pose'>): string {
  let sum = 0;
  for (const q of Object.values(picture.pose.joints)) sum += q.x + Math.SQRT2 * q.y;
  for (const q of Object.values(picture.pose.points)) sum += q.x + Math.SQRT2 * q.y;
  return sum.toPrecision(6);
}

/** Where a picture draws its chosen joint or tracer ("x y", length unit), or "" when none is chosen or drawn. */
export function selectedAt(picture: Pick<MechPicture, 'pose' | 'selected'>): string {
  const id = picture.selected;
  const at = id ? (picture.pose.joints[id] ?? picture.pose.points[id]) : undefined;
  return at ? `${at.x} ${at.y}` : '';
}
