import type { DrawContext } from '../../shared/canvas/drawContext';
import { THEME } from '../../shared/canvas/canvasTheme';
import type { ViewTransform } from '../../shared/canvas/view';
import { toScreenX, toScreenY } from '../../shared/canvas/view';
import { drawGroundTriangle, drawJoint, drawLink } from '../../shared/linkage/linkPrimitives';
import { TWO_PI } from '../../solver/angles';
import type { PlacedJoints } from '../../synthesis/types';

/** How a placed pose is drawn: the ground line dashed (Path mode: the design sits on the targets' plane) or solid. */
export interface PlacedPoseStyle {
  dashedGround?: boolean;
}

/**
 * The one drawing of a synthesised four-bar's pose (every synthesis canvas: Path, Motion, Function): the ground line
 * and its two pivots, the coupler plate A B P, crank, coupler and rocker, the joints, and P as the coupler point, in
 * CSS pixels through the view.
 */
export function drawPlacedPose(
  ctx: DrawContext,
  v: ViewTransform,
  j: PlacedJoints,
  { dashedGround = false }: PlacedPoseStyle = {},
): void {
  const [O2, A, B, O4, P] = [j.O2, j.A, j.B, j.O4, j.P].map((p) => ({ x: toScreenX(v, p.x), y: toScreenY(v, p.y) }));
  if (dashedGround) ctx.setLineDash([6, 4]);
  drawLink(ctx, O2, O4, THEME.ground, dashedGround ? 1.5 : 2);
  ctx.setLineDash([]);
  ctx.fillStyle = THEME.couplerFill;
  ctx.beginPath();
  ctx.moveTo(A.x, A.y);
  ctx.lineTo(B.x, B.y);
  ctx.lineTo(P.x, P.y);
  ctx.closePath();
  ctx.fill();
  drawLink(ctx, A, P, THEME.coupler, 2);
  drawLink(ctx, B, P, THEME.coupler, 2);
  drawLink(ctx, O2, A, THEME.crank, THEME.linkWidth);
  drawLink(ctx, A, B, THEME.coupler, THEME.linkWidth);
  drawLink(ctx, O4, B, THEME.rocker, THEME.linkWidth);
  drawGroundTriangle(ctx, O2, 9);
  drawGroundTriangle(ctx, O4, 9);
  for (const p of [O2, O4, A, B]) drawJoint(ctx, p, THEME.jointRadius);
  ctx.fillStyle = THEME.couplerPoint;
  ctx.beginPath();
  ctx.arc(P.x, P.y, 3.5, 0, TWO_PI);
  ctx.fill();
}
