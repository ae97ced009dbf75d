import { TWO_PI } from '../../solver/angles';
import type { DrawContext } from '../canvas/drawContext';
import { THEME } from '../canvas/canvasTheme';
import type { Px } from '../canvas/rect';
import { STROKES } from '../theme/tokens';
import { drawGroundTriangle, drawJoint, drawLink } from './linkPrimitives';

/** A four-bar's joints in CSS pixels of the canvas: the fixed pivots O2, O4, the moving A, B and the coupler point P. */
export interface FourBarPx {
  O2: Px;
  A: Px;
  B: Px;
  O4: Px;
  P: Px;
}

/**
 * How a canvas draws a four-bar's pose. The simulator draws its ground and pivots in its background and layers, and
 * marks P as a ring on the trace; a synthesis canvas draws the whole figure at once, P as a dot.
 */
export interface FourBarPoseStyle {
  /** The ground line O2 O4 and the pivots' signs and joints: none, a solid line, or a dashed one. */
  ground: 'none' | 'solid' | 'dashed';
  /** The coupler plate A B P: filled and outlined, or filled with its two edges to P drawn as bars. */
  plate: 'outlined' | 'edged';
  /** The coupler point P: a ring filled with the trace's colour, or a small dot. */
  couplerPoint: 'ring' | 'dot';
}

/** The simulator's style: its background draws the ground and its foreground the pivots. */
export const SIMULATOR_POSE: FourBarPoseStyle = { ground: 'none', plate: 'outlined', couplerPoint: 'ring' };

/** Radius of a synthesis canvas's fixed pivot sign (the triangle's half-width, CSS pixels). */
const PLACED_PIVOT_SIGN = 9;
/** Radius of a synthesis canvas's coupler point dot (CSS pixels). */
const PLACED_POINT_RADIUS = 3.5;

/** The coupler plate A B P: shaded so P reads as part of the rigid coupler. */
function drawPlate(ctx: DrawContext, { A, B, P }: FourBarPx, plate: FourBarPoseStyle['plate']): void {
  ctx.fillStyle = THEME.couplerFill;
  if (plate === 'outlined') {
    ctx.strokeStyle = THEME.coupler;
    ctx.lineWidth = STROKES.couplerPlate;
  }
  ctx.beginPath();
  ctx.moveTo(A.x, A.y);
  ctx.lineTo(B.x, B.y);
  ctx.lineTo(P.x, P.y);
  ctx.closePath();
  ctx.fill();
  if (plate === 'outlined') {
    ctx.stroke();
    return;
  }
  drawLink(ctx, A, P, THEME.coupler, 2);
  drawLink(ctx, B, P, THEME.coupler, 2);
}

function drawCouplerPoint(ctx: DrawContext, P: Px, style: FourBarPoseStyle['couplerPoint']): void {
  if (style === 'dot') {
    ctx.fillStyle = THEME.couplerPoint;
    ctx.beginPath();
    ctx.arc(P.x, P.y, PLACED_POINT_RADIUS, 0, TWO_PI);
    ctx.fill();
    return;
  }
  ctx.fillStyle = THEME.trace;
  ctx.strokeStyle = THEME.couplerPoint;
  ctx.lineWidth = STROKES.ground;
  ctx.beginPath();
  ctx.arc(P.x, P.y, STROKES.couplerPointRadius, 0, TWO_PI);
  ctx.fill();
  ctx.stroke();
}

/**
 * The one drawing of a four-bar's pose (the simulator's canvas, its export and live stage, and every synthesis
 * canvas): the ground and pivots if the style has them, the coupler plate, crank, coupler and rocker, the joints, and
 * the coupler point, in CSS pixels.
 */
export function drawFourBarPose(ctx: DrawContext, j: FourBarPx, style: FourBarPoseStyle): void {
  const { O2, A, B, O4, P } = j;
  if (style.ground !== 'none') {
    const dashed = style.ground === 'dashed';
    if (dashed) ctx.setLineDash([6, 4]);
    drawLink(ctx, O2, O4, THEME.ground, dashed ? 1.5 : 2);
    ctx.setLineDash([]);
  }
  drawPlate(ctx, j, style.plate);
  drawLink(ctx, O2, A, THEME.crank, STROKES.link);
  drawLink(ctx, A, B, THEME.coupler, STROKES.link);
  drawLink(ctx, B, O4, THEME.rocker, STROKES.link);
  if (style.ground !== 'none') {
    drawGroundTriangle(ctx, O2, PLACED_PIVOT_SIGN);
    drawGroundTriangle(ctx, O4, PLACED_PIVOT_SIGN);
    drawJoint(ctx, O2, STROKES.jointRadius);
    drawJoint(ctx, O4, STROKES.jointRadius);
  }
  drawJoint(ctx, A, STROKES.jointRadius);
  drawJoint(ctx, B, STROKES.jointRadius);
  drawCouplerPoint(ctx, P, style.couplerPoint);
}
