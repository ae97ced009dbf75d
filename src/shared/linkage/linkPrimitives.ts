import { TWO_PI } from '../../solver/angles';
import type { DrawContext } from '../canvas/drawContext';
import { THEME } from '../canvas/canvasTheme';
import { STROKES } from '../theme/tokens';

/** A point in CSS pixels. */
interface Px {
  x: number;
  y: number;
}

/** A link as a round-capped bar from a to b (CSS pixels). */
export function drawLink(ctx: DrawContext, a: Px, b: Px, color: string, width: number): void {
  ctx.strokeStyle = color;
  ctx.lineWidth = width;
  ctx.lineCap = 'round';
  ctx.beginPath();
  ctx.moveTo(a.x, a.y);
  ctx.lineTo(b.x, b.y);
  ctx.stroke();
}

/** A pin joint: a filled circle of radius r with an outline, in the joint colours unless given. */
export function drawJoint(
  ctx: DrawContext,
  p: Px,
  r: number,
  fill: string = THEME.joint,
  stroke: string = THEME.jointStroke,
): void {
  ctx.fillStyle = fill;
  ctx.strokeStyle = stroke;
  ctx.lineWidth = STROKES.jointOutline;
  ctx.beginPath();
  ctx.arc(p.x, p.y, r, 0, TWO_PI);
  ctx.fill();
  ctx.stroke();
}

/** The triangle of a fixed pivot's sign, its apex at p, half-width s and height 1.5 s (the base at p.y + 1.5 s). */
export function drawGroundTriangle(ctx: DrawContext, p: Px, s: number): void {
  ctx.fillStyle = THEME.groundFill;
  ctx.strokeStyle = THEME.ground;
  ctx.lineWidth = STROKES.ground;
  ctx.beginPath();
  ctx.moveTo(p.x, p.y);
  ctx.lineTo(p.x - s, p.y + s * 1.5);
  ctx.lineTo(p.x + s, p.y + s * 1.5);
  ctx.closePath();
  ctx.fill();
  ctx.stroke();
}
