import { GROUND } from '../../mechanism';
import type { MechanismSpec } from '../../mechanism';
import { TWO_PI } from '../../solver/angles';
import type { DrawContext } from '../../shared/canvas/drawContext';
import { THEME } from '../../shared/canvas/canvasTheme';
import { drawGrid } from '../../shared/canvas/drawGrid';
import type { Bounds, ViewTransform } from '../../shared/canvas/view';
import { emptyBounds, extendBounds, toScreenX, toScreenY } from '../../shared/canvas/view';
import { drawGroundPivot } from '../../shared/linkage/drawLinkage';
import { drawJoint, drawLink } from '../../shared/linkage/linkPrimitives';
import { COLORS, STROKES } from '../../shared/theme/tokens';
import type { MechPose, Pt } from './mechPose';
import { hull } from './hull';

/** Colours of the moving links, in the spec's order of links (the ground is grey). */
export const LINK_COLORS = [
  COLORS.crank,
  COLORS.coupler,
  COLORS.rocker,
  COLORS.couplerPoint,
  COLORS.velocity,
  COLORS.acceleration,
  '#4d7c0f',
  '#b45309',
] as const;

/** The colour of a link: grey for the ground, else LINK_COLORS by its place among the moving links. */
export function linkColor(spec: MechanismSpec, link: string): string {
  if (link === GROUND) return THEME.ground;
  const moving = spec.links.filter((l) => l !== GROUND);
  return LINK_COLORS[Math.max(0, moving.indexOf(link)) % LINK_COLORS.length];
}

/** A traced path (length unit; NaN: a gap). */
export interface MechTrace {
  id: string;
  x: ArrayLike<number>;
  y: ArrayLike<number>;
}

/** A velocity arrow at a point: its place and the vector (length per unit input rate), drawn to a common scale. */
export interface MechArrow {
  at: Pt;
  vx: number;
  vy: number;
}

/** What the mechanism canvas shows: the pose, the paths, the chosen joint, the arrows. */
export interface MechPicture {
  spec: MechanismSpec;
  pose: MechPose;
  traces: MechTrace[];
  /** Each slider's slide range over the run (block relative to guide, from as drawn), for the guides' lengths. */
  slideRange: Record<string, [number, number]>;
  selected: string | null;
  arrows: MechArrow[];
  /** Reaction arrows at the joints (N; the force on the joint's first link), drawn to their own scale; default none. */
  forceArrows?: MechArrow[];
  /** Drawn faint (the linkage cannot move as it is: mobility ≠ 1, or not assembled). */
  faint: boolean;
  /** A thumbnail: no grid and no names; default false. */
  compact?: boolean;
}

/** The world box of a picture: every joint and tracer, and the traces. */
export function pictureBounds(p: Pick<MechPicture, 'pose' | 'traces'>): Bounds {
  const b = emptyBounds();
  for (const q of [...Object.values(p.pose.joints), ...Object.values(p.pose.points)]) extendBounds(b, q.x, q.y);
  for (const t of p.traces) {
    for (let i = 0; i < t.x.length; i++) if (Number.isFinite(t.x[i])) extendBounds(b, t.x[i], t.y[i]);
  }
  return b;
}

/** A slider's slide direction at the pose: its drawn angle turned with its guide link. */
function slideDirection(j: MechanismSpec['joints'][number], pose: MechPose): number {
  return (j.angle ?? 0) + (j.links[1] === GROUND ? 0 : (pose.rotation[j.links[1]] ?? 0));
}

/** The ends of a slider's guide line at the pose (length unit): its slide range about the block, plus a margin. */
function guideEnds(pic: MechPicture, j: MechanismSpec['joints'][number], size: number): [Pt, Pt] {
  const at = pic.pose.joints[j.id];
  const dir = slideDirection(j, pic.pose);
  const [lo, hi] = pic.slideRange[j.id] ?? [0, 0];
  const now = pic.pose.slide[j.id] ?? 0;
  const m = 0.12 * size;
  const c = Math.cos(dir);
  const s = Math.sin(dir);
  const a = lo - now - m;
  const b = hi - now + m;
  return [
    { x: at.x + a * c, y: at.y + a * s },
    { x: at.x + b * c, y: at.y + b * s },
  ];
}

/**
 * Draws the linkage: background and grid, the traced paths, the moving links (a bar for two points, a filled
 * body for more, a slider's guide as a line in its link), the sliders' blocks, the fixed pivots, the joints (the
 * chosen one ringed) with their names, the tracers and the velocity arrows. Pure: context, picture and view.
 */
export function drawMechanism(ctx: DrawContext, pic: MechPicture, v: ViewTransform): void {
  drawMechanismBackground(ctx, pic, v);
  drawMechanismParts(ctx, pic, v);
}

/**
 * What drawMechanism draws first and what does not move with the input: the background, the grid and the traced
 * paths (a live stage keeps it in a bitmap while the traces and the view hold).
 */
export function drawMechanismBackground(
  ctx: DrawContext,
  pic: Pick<MechPicture, 'traces' | 'faint' | 'compact'>,
  v: ViewTransform,
): void {
  ctx.fillStyle = THEME.background;
  ctx.fillRect(0, 0, v.width, v.height);
  if (!pic.compact) drawGrid(ctx, v);
  ctx.globalAlpha = pic.faint ? 0.45 : 1;
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  ctx.lineWidth = STROKES.trace;
  ctx.strokeStyle = THEME.trace;
  for (const t of pic.traces) {
    ctx.beginPath();
    let pen = false;
    for (let i = 0; i < t.x.length; i++) {
      if (!Number.isFinite(t.x[i]) || !Number.isFinite(t.y[i])) {
        pen = false;
        continue;
      }
      const x = toScreenX(v, t.x[i]);
      const y = toScreenY(v, t.y[i]);
      if (pen) ctx.lineTo(x, y);
      else ctx.moveTo(x, y);
      pen = true;
    }
    ctx.stroke();
  }
  ctx.globalAlpha = 1;
}

/** What drawMechanism draws over the background and the traces: the links, blocks, pivots, joints, arrows and names. */
export function drawMechanismParts(ctx: DrawContext, pic: MechPicture, v: ViewTransform): void {
  const { spec, pose } = pic;
  const px = (p: Pt) => ({ x: toScreenX(v, p.x), y: toScreenY(v, p.y) });
  ctx.globalAlpha = pic.faint ? 0.45 : 1;
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  const size = Math.max(1e-12, (v.width + v.height) / 2 / v.scale / 3);
  // Fixed guides (a slider on the ground): a dashed line along the stroke.
  for (const j of spec.joints) {
    if (j.kind !== 'P' || j.links[1] !== GROUND || !pose.joints[j.id]) continue;
    const [a, b] = guideEnds(pic, j, size);
    ctx.strokeStyle = THEME.ground;
    ctx.lineWidth = STROKES.ground;
    ctx.setLineDash([6, 4]);
    ctx.beginPath();
    ctx.moveTo(px(a).x, px(a).y);
    ctx.lineTo(px(b).x, px(b).y);
    ctx.stroke();
    ctx.setLineDash([]);
  }
  // Moving links: the hull of their points (joints, tracers, guide ends), filled faintly, outlined in the link's colour.
  for (const link of spec.links) {
    if (link === GROUND) continue;
    const pts: Pt[] = [];
    const guides: [Pt, Pt][] = [];
    for (const j of spec.joints) {
      const at = pose.joints[j.id];
      if (!at) continue;
      if (j.kind === 'R' && j.links.includes(link)) pts.push(at);
      if (j.kind === 'P' && j.links[0] === link) pts.push(at);
      if (j.kind === 'P' && j.links[1] === link) guides.push(guideEnds(pic, j, size));
    }
    for (const p of spec.points ?? []) if (p.link === link && pose.points[p.id]) pts.push(pose.points[p.id]);
    const color = linkColor(spec, link);
    for (const [a, b] of guides) {
      // A slot: a wide pale bar with the link's line along it.
      drawLink(ctx, px(a), px(b), `${color}33`, 12);
      drawLink(ctx, px(a), px(b), color, 2);
      pts.push({ x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 });
    }
    const h = hull(pts).map(px);
    if (h.length >= 3) {
      ctx.fillStyle = `${color}22`;
      ctx.strokeStyle = color;
      ctx.lineWidth = STROKES.link * 0.6;
      ctx.beginPath();
      h.forEach((q, i) => (i === 0 ? ctx.moveTo(q.x, q.y) : ctx.lineTo(q.x, q.y)));
      ctx.closePath();
      ctx.fill();
      ctx.stroke();
    } else if (h.length === 2) {
      drawLink(ctx, h[0], h[1], color, STROKES.link);
    }
  }
  // Sliders' blocks: a rectangle along the slide, in the block link's colour (grey when the block is the ground).
  for (const j of spec.joints) {
    const at = pose.joints[j.id];
    if (j.kind !== 'P' || !at) continue;
    const p = px(at);
    const dir = slideDirection(j, pose);
    ctx.save();
    ctx.translate(p.x, p.y);
    ctx.rotate(-dir);
    ctx.fillStyle = THEME.joint;
    ctx.strokeStyle = linkColor(spec, j.links[0]);
    ctx.lineWidth = 2.5;
    ctx.beginPath();
    ctx.roundRect(-16, -9, 32, 18, 3);
    ctx.fill();
    ctx.stroke();
    ctx.restore();
  }
  // Fixed pivots, then every pin.
  for (const j of spec.joints) {
    const at = pose.joints[j.id];
    if (j.kind === 'R' && at && j.links.includes(GROUND)) drawGroundPivot(ctx, px(at));
  }
  for (const j of spec.joints) {
    const at = pose.joints[j.id];
    if (!at) continue;
    const p = px(at);
    if (j.kind === 'R') drawJoint(ctx, p, STROKES.jointRadius);
    if (spec.input.joint === j.id) {
      ctx.strokeStyle = COLORS.accent2;
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.arc(p.x, p.y, STROKES.jointRadius + 5, 0.3, TWO_PI - 0.3);
      ctx.stroke();
    }
  }
  for (const t of spec.points ?? []) {
    const at = pose.points[t.id];
    if (at) drawJoint(ctx, px(at), STROKES.couplerPointRadius, THEME.couplerPoint, THEME.jointStroke);
  }
  ctx.globalAlpha = 1;
  drawArrows(ctx, pic.arrows, v, THEME.velocity);
  drawArrows(ctx, pic.forceArrows ?? [], v, COLORS.force);
  // The chosen joint: a ring in the accent colour.
  const sel = pic.selected ? (pose.joints[pic.selected] ?? pose.points[pic.selected]) : null;
  if (sel) {
    const p = px(sel);
    ctx.strokeStyle = COLORS.accent2;
    ctx.lineWidth = 2.5;
    ctx.beginPath();
    ctx.arc(p.x, p.y, STROKES.jointRadius + 9, 0, TWO_PI);
    ctx.stroke();
  }
  if (!pic.compact) drawNames(ctx, pic, v);
}

/** Arrows in one colour, scaled together so that the longest is about a fifth of the view's smaller side. */
function drawArrows(ctx: DrawContext, arrows: MechArrow[], v: ViewTransform, color: string): void {
  let longest = 0;
  for (const a of arrows)
    if (Number.isFinite(a.vx) && Number.isFinite(a.vy)) longest = Math.max(longest, Math.hypot(a.vx, a.vy));
  if (!(longest > 0)) return;
  const k = Math.min(v.width, v.height) / 5 / longest;
  ctx.strokeStyle = color;
  ctx.fillStyle = color;
  ctx.lineWidth = 2;
  for (const a of arrows) {
    if (!Number.isFinite(a.vx) || !Number.isFinite(a.vy)) continue;
    const x0 = toScreenX(v, a.at.x);
    const y0 = toScreenY(v, a.at.y);
    const dx = a.vx * k;
    const dy = -a.vy * k;
    const len = Math.hypot(dx, dy);
    if (len < 2) continue;
    const ux = dx / len;
    const uy = dy / len;
    ctx.beginPath();
    ctx.moveTo(x0, y0);
    ctx.lineTo(x0 + dx, y0 + dy);
    ctx.stroke();
    ctx.beginPath();
    ctx.moveTo(x0 + dx, y0 + dy);
    ctx.lineTo(x0 + dx - 9 * ux + 4.5 * uy, y0 + dy - 9 * uy - 4.5 * ux);
    ctx.lineTo(x0 + dx - 9 * ux - 4.5 * uy, y0 + dy - 9 * uy + 4.5 * ux);
    ctx.closePath();
    ctx.fill();
  }
}

/** Every joint's and tracer's name beside it, on a halo, up and to the right. */
function drawNames(ctx: DrawContext, pic: MechPicture, v: ViewTransform): void {
  ctx.font = THEME.font;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'bottom';
  ctx.lineWidth = 3;
  ctx.strokeStyle = THEME.labelHalo;
  ctx.fillStyle = THEME.text;
  const named: [string, Pt | undefined][] = [
    ...pic.spec.joints.map((j) => [j.id, pic.pose.joints[j.id]] as [string, Pt | undefined]),
    ...(pic.spec.points ?? []).map((p) => [p.id, pic.pose.points[p.id]] as [string, Pt | undefined]),
  ];
  for (const [id, at] of named) {
    if (!at) continue;
    const x = toScreenX(v, at.x) + 9;
    const y = toScreenY(v, at.y) - 7;
    ctx.strokeText(id, x, y);
    ctx.fillText(id, x, y);
  }
}
