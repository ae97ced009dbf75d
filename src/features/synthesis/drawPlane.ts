/**
 * Drawing primitives of the synthesis page's canvases (Motion and Function modes): the grid, a placed four-bar,
 * markers and polylines, each a pure function of (context, data, view) in CSS pixels.
 */
import { drawGrid } from '../../shared/canvas/drawGrid';
import { drawPlacedPose } from './drawPlacedPose';
import { drawLink } from '../../shared/linkage/linkPrimitives';
import { TWO_PI } from '../../solver';
import type { Point } from '../../solver';
import { placedJoints } from '../../synthesis';
import type { PlacedFourBar } from '../../synthesis';
import type { DrawContext } from '../../shared/canvas/drawContext';
import { THEME } from '../../shared/canvas/canvasTheme';
import type { ViewTransform } from '../../shared/canvas/view';
import type { Px } from '../../shared/canvas/rect';
import { toScreenX, toScreenY } from '../../shared/canvas/view';

/** The CSS pixel of a world point. */
export function px(v: ViewTransform, p: Point): Px {
  return { x: toScreenX(v, p.x), y: toScreenY(v, p.y) };
}

/** Clears to the surface colour and draws the grid about 64 px apart with the axes darker. */
export function drawBackground(ctx: DrawContext, v: ViewTransform): void {
  ctx.fillStyle = THEME.background;
  ctx.fillRect(0, 0, v.width, v.height);
  drawGrid(ctx, v);
}

/** A polyline through world points (null: a gap), in one colour, width and dash. */
export function drawPolyline(
  ctx: DrawContext,
  v: ViewTransform,
  points: readonly (Point | null)[],
  color: string,
  width: number,
  dash: number[] = [],
): void {
  ctx.strokeStyle = color;
  ctx.lineWidth = width;
  ctx.setLineDash(dash);
  ctx.beginPath();
  let pen = false;
  for (const p of points) {
    if (!p) {
      pen = false;
      continue;
    }
    const s = px(v, p);
    // Points far off screen would overflow the canvas's fixed-point path: break the line there instead.
    if (Math.abs(s.x) > 1e5 || Math.abs(s.y) > 1e5) {
      pen = false;
      continue;
    }
    if (pen) ctx.lineTo(s.x, s.y);
    else ctx.moveTo(s.x, s.y);
    pen = true;
  }
  ctx.stroke();
  ctx.setLineDash([]);
}

/** A circle of radius r (world units) about c, thin. */
export function drawWorldCircle(
  ctx: DrawContext,
  v: ViewTransform,
  c: Point,
  r: number,
  color: string,
  dash: number[] = [],
): void {
  const s = px(v, c);
  const rp = r * v.scale;
  if (!(rp > 0) || rp > 1e5) return;
  ctx.strokeStyle = color;
  ctx.lineWidth = 1;
  ctx.setLineDash(dash);
  ctx.beginPath();
  ctx.arc(s.x, s.y, rp, 0, TWO_PI);
  ctx.stroke();
  ctx.setLineDash([]);
}

/** The shape of a point marker. */
export type MarkerShape = 'dot' | 'ring' | 'diamond' | 'hollowDiamond' | 'cross';

/** A marker of radius r CSS pixels at a world point. */
export function drawMarker(
  ctx: DrawContext,
  v: ViewTransform,
  p: Point,
  shape: MarkerShape,
  color: string,
  r = 4,
): void {
  const s = px(v, p);
  ctx.strokeStyle = color;
  ctx.fillStyle = color;
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  if (shape === 'dot' || shape === 'ring') {
    ctx.arc(s.x, s.y, r, 0, TWO_PI);
  } else if (shape === 'cross') {
    ctx.moveTo(s.x - r, s.y - r);
    ctx.lineTo(s.x + r, s.y + r);
    ctx.moveTo(s.x - r, s.y + r);
    ctx.lineTo(s.x + r, s.y - r);
    ctx.stroke();
    return;
  } else {
    ctx.moveTo(s.x, s.y - r - 1);
    ctx.lineTo(s.x + r + 1, s.y);
    ctx.lineTo(s.x, s.y + r + 1);
    ctx.lineTo(s.x - r - 1, s.y);
    ctx.closePath();
  }
  if (shape === 'dot' || shape === 'diamond') ctx.fill();
  else {
    ctx.fillStyle = THEME.background;
    ctx.fill();
    ctx.stroke();
  }
}

/** A short text beside a world point, with a halo so it reads over lines. */
export function drawLabel(ctx: DrawContext, v: ViewTransform, p: Point, text: string, dx = 8, dy = -8): void {
  const s = px(v, p);
  ctx.font = THEME.font;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'middle';
  ctx.lineWidth = 3;
  ctx.strokeStyle = THEME.labelHalo;
  ctx.strokeText(text, s.x + dx, s.y + dy);
  ctx.fillStyle = THEME.text;
  ctx.fillText(text, s.x + dx, s.y + dy);
}

/**
 * A placed four-bar at θ2 (radians, from its ground line): ground, crank, the coupler triangle A B P, rocker and
 * joints, solid; or, with ghost, thin in the ghost colour (its other poses). Nothing where the loop cannot close.
 * Returns the joints drawn (null when none).
 */
export function drawFourBar(
  ctx: DrawContext,
  v: ViewTransform,
  design: PlacedFourBar,
  theta2: number,
  ghost = false,
): ReturnType<typeof placedJoints> {
  const j = placedJoints(design, theta2);
  if (!j) return null;
  const O2 = px(v, j.O2);
  const A = px(v, j.A);
  const B = px(v, j.B);
  const O4 = px(v, j.O4);
  const P = px(v, j.P);
  if (ghost) {
    ctx.globalAlpha = 0.45;
    for (const [a, b] of [
      [O2, A],
      [A, B],
      [B, O4],
      [A, P],
      [B, P],
    ] as const) {
      drawLink(ctx, a, b, THEME.ghost, 1.5);
    }
    ctx.globalAlpha = 1;
    return j;
  }
  drawPlacedPose(ctx, v, j);
  return j;
}
