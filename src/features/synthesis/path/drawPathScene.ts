import { drawGrid } from '../../../shared/canvas/drawGrid';
import { drawPlacedPose } from '../drawPlacedPose';
import { drawLink } from '../../../shared/linkage/linkPrimitives';
import { TWO_PI } from '../../../solver/angles';
import type { Point } from '../../../solver/kinematics';
import type { PlacedFourBar, PlacedJoints } from '../../../synthesis/types';
import type { DrawContext } from '../../../shared/canvas/drawContext';
import type { Bounds, ViewTransform } from '../../../shared/canvas/view';
import { emptyBounds, extendBounds, extendBoundsCircle, toScreenX, toScreenY } from '../../../shared/canvas/view';
import { COLORS, FONTS, FONT_SIZES, STROKES } from '../../../shared/theme/tokens';

/** A coupler curve to draw (length unit); NaN breaks it. Faint curves are the other choices (cognates). */
export interface PathCurve {
  x: ArrayLike<number>;
  y: ArrayLike<number>;
  faint: boolean;
}

/** What the synthesis canvas shows: the targets (one selected), curves and the chosen linkage's pose. */
export interface PathScene {
  targets: readonly Point[];
  selected: number | null;
  /** Target names, as drawn beside them (T1, T2, …). */
  names: readonly string[];
  curves: readonly PathCurve[];
  pose: PlacedJoints | null;
}

/** Radius of a target's ring (CSS pixels), and of the selected one's. */
export const TARGET_RADIUS_PX = 6;
const SELECTED_RADIUS_PX = 8;

/** World bounds of a scene: targets, curves, the pose's pivots and a design's crank and rocker circles (nothing: a box about the origin). */
export function pathSceneBounds(
  scene: Pick<PathScene, 'targets' | 'curves' | 'pose'> & { design?: PlacedFourBar | null },
): Bounds {
  const b = emptyBounds();
  for (const p of scene.targets) extendBounds(b, p.x, p.y);
  for (const c of scene.curves) for (let i = 0; i < c.x.length; i++) extendBounds(b, c.x[i], c.y[i]);
  if (scene.pose) for (const p of [scene.pose.O2, scene.pose.O4]) extendBounds(b, p.x, p.y);
  if (scene.design) {
    // The crank and rocker circles hold every pose of the linkage.
    const { O2, groundAngle, links } = scene.design;
    const O4 = { x: O2.x + links.r1 * Math.cos(groundAngle), y: O2.y + links.r1 * Math.sin(groundAngle) };
    extendBoundsCircle(b, O2.x, O2.y, links.r2);
    extendBoundsCircle(b, O4.x, O4.y, links.r4);
  }
  if (!(b.minX <= b.maxX)) return { minX: -5, minY: -5, maxX: 5, maxY: 5 };
  return b;
}

function px(v: ViewTransform, p: Point): Point {
  return { x: toScreenX(v, p.x), y: toScreenY(v, p.y) };
}

function drawCurve(ctx: DrawContext, v: ViewTransform, c: PathCurve): void {
  ctx.strokeStyle = c.faint ? COLORS.ghost : COLORS.trace;
  ctx.lineWidth = c.faint ? 1 : STROKES.trace;
  ctx.setLineDash(c.faint ? [5, 4] : []);
  ctx.beginPath();
  let pen = false;
  for (let i = 0; i < c.x.length; i++) {
    if (!Number.isFinite(c.x[i]) || !Number.isFinite(c.y[i])) {
      pen = false;
      continue;
    }
    const sx = toScreenX(v, c.x[i]);
    const sy = toScreenY(v, c.y[i]);
    if (pen) ctx.lineTo(sx, sy);
    else ctx.moveTo(sx, sy);
    pen = true;
  }
  ctx.stroke();
  ctx.setLineDash([]);
}

function drawTargets(ctx: DrawContext, v: ViewTransform, scene: PathScene): void {
  ctx.font = `600 ${FONT_SIZES.canvas}px ${FONTS.sans}`;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'bottom';
  scene.targets.forEach((t, i) => {
    const p = px(v, t);
    const on = scene.selected === i;
    ctx.strokeStyle = COLORS.accent2;
    ctx.fillStyle = on ? COLORS.accent2 : COLORS.surface;
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.arc(p.x, p.y, on ? SELECTED_RADIUS_PX : TARGET_RADIUS_PX, 0, TWO_PI);
    ctx.fill();
    ctx.stroke();
    // A cross in the ring marks the exact point.
    drawLink(ctx, { x: p.x - 3, y: p.y }, { x: p.x + 3, y: p.y }, on ? COLORS.surface : COLORS.accent2, 1.5);
    drawLink(ctx, { x: p.x, y: p.y - 3 }, { x: p.x, y: p.y + 3 }, on ? COLORS.surface : COLORS.accent2, 1.5);
    const name = scene.names[i] ?? '';
    ctx.lineWidth = 3;
    ctx.strokeStyle = COLORS.labelHalo;
    ctx.strokeText(name, p.x + 8, p.y - 6);
    ctx.fillStyle = COLORS.text;
    ctx.fillText(name, p.x + 8, p.y - 6);
  });
}

/**
 * Draws the synthesis canvas (a pure function of context, scene and view): background, grid, the curves (faint
 * first), the chosen linkage's pose and the targets with their names on top. Any DrawContext: a canvas's or the
 * SVG export's.
 */
export function drawPathScene(ctx: DrawContext, scene: PathScene, v: ViewTransform): void {
  ctx.fillStyle = COLORS.surface;
  ctx.fillRect(0, 0, v.width, v.height);
  drawGrid(ctx, v);
  for (const c of scene.curves) if (c.faint) drawCurve(ctx, v, c);
  for (const c of scene.curves) if (!c.faint) drawCurve(ctx, v, c);
  if (scene.pose) drawPlacedPose(ctx, v, scene.pose, { dashedGround: true });
  drawTargets(ctx, v, scene);
}
