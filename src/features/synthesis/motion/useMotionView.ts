import { useMemo, useState } from 'react';
import type { Point } from '../../../solver';
import type { BurmesterPair } from '../../../synthesis';
import type { SynMotionState } from '../../../shared/state/slices/synMotionSlice';
import type { MotionMessages } from './motionMessages';
import type { MotionOutcome } from './motionSolve';
import { toPose } from './motionSolve';
import type { MotionPicture } from './motionPicture';
import { centroid, nearestSample } from './motionPicture';

/** The centre of the sampled dyad within reach of at (world units), the nearest; null where none is. */
export function dyadCentreNear(samples: readonly BurmesterPair[], at: Point, reach: number): Point | null {
  let best: Point | null = null;
  let bestD = reach;
  for (const d of samples) {
    const dist = Math.hypot(d.center.x - at.x, d.center.y - at.y);
    if (dist <= bestD) {
      bestD = dist;
      best = d.center;
    }
  }
  return best;
}

/**
 * What the Motion mode's view holds besides the state: the selected pose, the pose the design is shown at, the
 * curve slider's sample (until it is moved, the one nearest the poses, so its mark is in view), each clamped to what
 * there is; and the picture the canvas draws from them.
 */
export function useMotionView(s: SynMotionState, outcome: MotionOutcome, mt: MotionMessages) {
  const [selectedRaw, setSelected] = useState(0);
  const [shownRaw, setShown] = useState(0);
  const [cursorRaw, setCursor] = useState<number | null>(null);
  const selected = Math.min(selectedRaw, s.poses.length - 1);
  const shownPose = Math.min(shownRaw, (outcome.chosen?.theta2.length ?? 1) - 1);
  const poses = useMemo(() => s.poses.map(toPose), [s.poses]);
  const samples = useMemo(() => (outcome.count === 4 ? outcome.curves.flat() : []), [outcome]);
  const cursor = Math.min(cursorRaw ?? nearestSample(samples, centroid(poses)), Math.max(0, samples.length - 1));
  const picture: MotionPicture = {
    poses,
    selected,
    outcome,
    pivotChoice: s.pivotChoice,
    pivots: s.pivots,
    shownPose,
    cursor: samples[cursor] ?? null,
    legend: { centre: mt.centreCurve, circle: mt.circleCurve },
  };
  return { picture, poses, samples, selected, setSelected, shownPose, setShown, cursor, setCursor };
}
