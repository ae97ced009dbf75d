import type { Point } from '../../../solver/kinematics';
import type { Bounds } from '../../../shared/canvas/view';
import type { MotionRange } from './candidateFacts';
import type { PathCurve } from './drawPathScene';
import { pathSceneBounds } from './drawPathScene';
import type { PlacedFourBar } from '../../../synthesis/types';
import type { TimedChoice } from './usePathChoices';
import { useFitBounds } from './useFitBounds';

/** What the Path mode's canvas draws besides the targets: the curves, the moving linkage and the bounds it fits. */
export interface PathPicture {
  curves: PathCurve[];
  moving: { design: PlacedFourBar; motion: MotionRange } | null;
  bounds: Bounds;
}

/**
 * The Path mode's canvas content: every choice's coupler curve (faint but the one shown; all faint when stale), the
 * shown linkage moving (not when stale), and the bounds fitted to the targets, the shown curve and linkage, refitted
 * when fitKey changes.
 */
export function usePathPicture(
  targets: readonly Point[],
  choices: readonly TimedChoice[],
  shown: number,
  stale: boolean,
  fitKey: string,
): PathPicture {
  const choice = choices[Math.min(shown, choices.length - 1)] ?? null;
  const curves: PathCurve[] = choice
    ? choices.map((c) => ({ x: c.facts.curve.x, y: c.facts.curve.y, faint: stale || c !== choice }))
    : [];
  const moving = choice && !stale ? { design: choice.design, motion: choice.facts.motion } : null;
  const content = pathSceneBounds({
    targets,
    curves: choice ? [curves[Math.min(shown, curves.length - 1)]] : [],
    pose: null,
    design: choice?.design ?? null,
  });
  const bounds = useFitBounds(content, fitKey);
  return { curves, moving, bounds };
}
