/**
 * The Function mode's canvas as a pure function of (context, picture, view): the linkage at the current x, the θ2
 * range as an arc about O2 and the θ4 range about O4 with the precision points ticked on both, the other
 * precision poses as ghosts.
 */
import type { Point } from '../../../solver';
import type { DrawContext } from '../../../shared/canvas/drawContext';
import { THEME } from '../../../shared/canvas/canvasTheme';
import type { Bounds, ViewTransform } from '../../../shared/canvas/view';
import { emptyBounds, extendBoundsCircle } from '../../../shared/canvas/view';
import { drawBackground, drawFourBar, drawLabel, drawPolyline } from '../drawPlane';
import type { FunctionDesign } from './functionSolve';

/** Everything the Function canvas draws: the design, its ranges (radians) and the current input angle. */
export interface FunctionPicture {
  fd: FunctionDesign;
  theta2Range: [number, number];
  theta4Range: [number, number];
  /** The input angle shown (radians, from the ground line). */
  theta2: number;
}

/** The box the view fits: both pivots with their links' circles, so the whole motion stays in view. */
export function functionBounds(pic: FunctionPicture): Bounds {
  const { links } = pic.fd.result;
  const b = emptyBounds();
  extendBoundsCircle(b, 0, 0, links.r2 * 1.35);
  extendBoundsCircle(b, links.r1, 0, links.r4 * 1.35);
  return b;
}

/** An arc of radius r (world) about c from angle a0 to a1 (radians), with ticks at the given angles. */
function rangeArc(
  ctx: DrawContext,
  v: ViewTransform,
  c: Point,
  r: number,
  [a0, a1]: [number, number],
  ticks: readonly number[],
  color: string,
): void {
  const n = 64;
  const at = (a: number, k = 1) => ({ x: c.x + k * r * Math.cos(a), y: c.y + k * r * Math.sin(a) });
  drawPolyline(
    ctx,
    v,
    Array.from({ length: n + 1 }, (_, i) => at(a0 + ((a1 - a0) * i) / n)),
    color,
    2,
  );
  for (const a of ticks) drawPolyline(ctx, v, [at(a, 0.9), at(a, 1.1)], color, 2);
}

/** Draws the whole Function canvas. */
export function drawFunction(ctx: DrawContext, pic: FunctionPicture, v: ViewTransform): void {
  drawBackground(ctx, v);
  const { links } = pic.fd.result;
  const O4 = { x: links.r1, y: 0 };
  const origin = { x: 0, y: 0 };
  rangeArc(
    ctx,
    v,
    origin,
    links.r2 * 1.25,
    pic.theta2Range,
    pic.fd.precision.map((p) => p.theta2),
    THEME.crank,
  );
  rangeArc(
    ctx,
    v,
    O4,
    links.r4 * 1.25,
    pic.theta4Range,
    pic.fd.precision.map((p) => p.theta4),
    THEME.rocker,
  );
  for (const p of pic.fd.precision) drawFourBar(ctx, v, pic.fd.design, p.theta2, true);
  drawFourBar(ctx, v, pic.fd.design, pic.theta2);
  drawLabel(ctx, v, origin, 'O2', -22, 22);
  drawLabel(ctx, v, O4, 'O4', 10, 22);
}
