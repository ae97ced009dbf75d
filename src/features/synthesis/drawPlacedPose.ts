import type { DrawContext } from '../../shared/canvas/drawContext';
import type { ViewTransform } from '../../shared/canvas/view';
import { toScreenX, toScreenY } from '../../shared/canvas/view';
import { drawFourBarPose } from '../../shared/linkage/drawFourBarPose';
import type { PlacedJoints } from '../../synthesis/types';

/** How a placed pose is drawn: the ground line dashed (Path mode: the design sits on the targets' plane) or solid. */
export interface PlacedPoseStyle {
  dashedGround?: boolean;
}

/**
 * A synthesised four-bar's pose on a synthesis canvas (Path, Motion, Function), through the view: the one four-bar
 * drawer (drawFourBarPose) with the ground and its pivots, the plate's edges to P as bars and P as a dot.
 */
export function drawPlacedPose(
  ctx: DrawContext,
  v: ViewTransform,
  j: PlacedJoints,
  { dashedGround = false }: PlacedPoseStyle = {},
): void {
  const [O2, A, B, O4, P] = [j.O2, j.A, j.B, j.O4, j.P].map((p) => ({ x: toScreenX(v, p.x), y: toScreenY(v, p.y) }));
  drawFourBarPose(
    ctx,
    { O2, A, B, O4, P },
    { ground: dashedGround ? 'dashed' : 'solid', plate: 'edged', couplerPoint: 'dot' },
  );
}
