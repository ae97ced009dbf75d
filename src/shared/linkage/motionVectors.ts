import type { DrawContext } from '../canvas/drawContext';
import { drawPanelBox } from '../canvas/drawContext';
import { PI } from '../../solver/angles';
import { FONT_SIZES, STROKES } from '../theme/tokens';
import type { Obstacle } from '../canvas/labelPlacement';
import type { Px, ScreenRect } from '../canvas/rect';
import { candidatesAround } from '../canvas/labelPlacement';
import type { ScenePose } from './scene';
import type { ExtraLabel, MeasureText, SceneExtras } from './sceneLayout';
import { LABEL_PAD_Y } from './sceneLayout';
import { THEME } from '../canvas/canvasTheme';
import type { ViewTransform } from '../canvas/view';
import { frameToScreen } from '../canvas/view';

type Ctx = DrawContext;

/** The points that carry arrows. */
export type VectorPoint = 'A' | 'B' | 'P';

/** Velocity ('v') or acceleration ('a'). */
export type VectorKind = 'v' | 'a';

/** A world vector (length/s or length/s², y up); NaN components where it is undetermined (a limit position). */
export interface WorldVector {
  x: number;
  y: number;
}

/** What an arrow length means: the scale bar shows `value` (length/s or length/s²) as barPx CSS pixels. */
export interface ArrowScale {
  value: number;
  barPx: number;
  /** CSS pixels per length/s (or length/s²) for every arrow of this kind. */
  pxPerUnit: number;
}

/** Texts of the vector overlay, already in the UI language. */
export interface VectorText {
  /** Arrow labels, e.g. { v: 'v', a: 'a' } giving vA, aP. */
  symbol: Record<VectorKind, string>;
  /** Scale-bar rows: what the bar's length means, from the formatted value. */
  velocityBar: (value: string) => string;
  accelerationBar: (value: string) => string;
  /** Row shown when an arrow kind is zero everywhere (no scale). */
  zero: string;
  /** Row shown when some arrow is clamped (drawn dashed, not to scale). */
  clamped: string;
  /** Row shown at a limit position (no arrows at B and P). */
  limit: string;
  formatValue: (x: number) => string;
}

/** The vectors to draw at this frame: null kinds are off; scales stay put while the linkage moves. */
export interface SceneVectors {
  velocity: Record<VectorPoint, WorldVector> | null;
  acceleration: Record<VectorPoint, WorldVector> | null;
  velocityScale: ArrowScale | null;
  accelerationScale: ArrowScale | null;
  limit: boolean;
  text: VectorText;
}

/** How an arrow was drawn: to scale, lengthened to the shortest readable length, or cut to the longest. */
export type ArrowClamp = 'none' | 'short' | 'long';

/** Shortest and longest arrow drawn (CSS pixels); arrows beyond are clamped, dashed and said so in the legend. */
export const ARROW_MIN_PX = 12;
export const ARROW_MAX_PX = 150;
/** Length (CSS pixels) a typical magnitude is drawn at; the bar shows a round value near it. */
export const ARROW_TARGET_PX = 60;

/**
 * The scale of one arrow kind from a typical magnitude (r2 |omega2| for velocities): the bar shows the
 * largest 1, 2 or 5 times a power of ten not above it, and the typical magnitude is drawn ARROW_TARGET_PX
 * long (so the bar is 24 to 60 px). Null when the typical magnitude is 0 or not finite (nothing to scale).
 */
export function arrowScale(typical: number, targetPx: number = ARROW_TARGET_PX): ArrowScale | null {
  if (!(typical > 0) || !Number.isFinite(typical)) return null;
  const p = 10 ** Math.floor(Math.log10(typical));
  let value = p;
  for (const m of [2, 5, 10]) if (m * p <= typical * (1 + 1e-12)) value = m * p;
  const pxPerUnit = targetPx / typical;
  return { value, barPx: value * pxPerUnit, pxPerUnit };
}

/**
 * An arrow's drawn length (CSS pixels) for a magnitude: magnitude * pxPerUnit within [minPx, maxPx], and
 * which clamp applied. Null for a zero or non-finite magnitude (no direction to draw).
 */
export function arrowLength(
  magnitude: number,
  pxPerUnit: number,
  minPx: number = ARROW_MIN_PX,
  maxPx: number = ARROW_MAX_PX,
): { lengthPx: number; clamp: ArrowClamp } | null {
  if (!(magnitude > 0) || !Number.isFinite(magnitude) || !(pxPerUnit > 0)) return null;
  const l = magnitude * pxPerUnit;
  if (l < minPx) return { lengthPx: minPx, clamp: 'short' };
  if (l > maxPx) return { lengthPx: maxPx, clamp: 'long' };
  return { lengthPx: l, clamp: 'none' };
}

/** One arrow in CSS pixels. */
export interface VectorArrow {
  kind: VectorKind;
  at: VectorPoint;
  from: Px;
  to: Px;
  clamp: ArrowClamp;
  color: string;
}

/** One row of the scale legend: a bar of barPx (0: none) in a colour, then its text. */
export interface LegendRow {
  barPx: number;
  color: string;
  text: string;
  dashed: boolean;
}

/** The scale legend: its box (CSS pixels, bottom right) and rows. */
export interface VectorLegend {
  box: ScreenRect;
  rows: LegendRow[];
}

/** The overlay to draw: arrows, the legend, and the labels and obstacles layoutScene places with the scene's. */
export interface VectorOverlay {
  arrows: VectorArrow[];
  legend: VectorLegend | null;
  /** The legend's box, for layoutScene's exclusions. */
  exclusions: ScreenRect[];
  extras: SceneExtras;
}

/** Legend geometry (CSS pixels): margin from the canvas corner, padding, row height, gap between bar and text. */
export const LEGEND = { margin: 8, pad: 6, rowPx: 16, gapPx: 6 } as const;

/** Turns from an arrow's direction: straight beyond its tip first, then turning away either side. */
const TIP_ROTATIONS = [0, 1, -1, 2, -2, 3, -3, 4, -4].map((k) => (k * PI) / 6);

/** Centres around an arrow's tip: straight beyond it first, then turning away, at growing gaps. */
function aroundTip(tip: Px, ux: number, uy: number, width: number, height: number): Px[] {
  return candidatesAround(tip, { x: ux, y: uy }, TIP_ROTATIONS, [3, 9, 18], 0, width, height);
}

/** One kind of arrow to draw: its kind, the world vectors at A, B and P (null: not shown), its scale and colour. */
type KindPlan = [VectorKind, Record<VectorPoint, WorldVector> | null, ArrowScale | null, string];

/** The rows of the scale legend: one per kind shown, then the clamped and limit notes when they apply. */
function legendRows(vectors: SceneVectors, kinds: readonly KindPlan[], anyClamped: boolean): LegendRow[] {
  const t = vectors.text;
  const rows: LegendRow[] = [];
  for (const [kind, vs, scale, color] of kinds) {
    if (!vs) continue;
    const bar = kind === 'v' ? t.velocityBar : t.accelerationBar;
    rows.push(
      scale
        ? { barPx: scale.barPx, color, text: bar(t.formatValue(scale.value)), dashed: false }
        : { barPx: 0, color, text: `${t.symbol[kind]}: ${t.zero}`, dashed: false },
    );
  }
  if (anyClamped) rows.push({ barPx: 24, color: THEME.textMuted, text: t.clamped, dashed: true });
  if (vectors.limit && rows.length > 0) rows.push({ barPx: 0, color: THEME.warning, text: t.limit, dashed: false });
  return rows;
}

/** The legend's box in the bottom-right corner, sized to its widest row; null without rows. */
function placeLegend(rows: LegendRow[], view: ViewTransform, measure: MeasureText): VectorLegend | null {
  if (rows.length === 0) return null;
  let w = 0;
  for (const r of rows) w = Math.max(w, (r.barPx > 0 ? r.barPx + LEGEND.gapPx : 0) + measure(r.text, 'regular'));
  const width = w + 2 * LEGEND.pad;
  const height = rows.length * LEGEND.rowPx + 2 * LEGEND.pad - 4;
  return {
    box: { x: view.width - LEGEND.margin - width, y: view.height - LEGEND.margin - height, width, height },
    rows,
  };
}

/**
 * Lays out the vector overlay for a pose: an arrow at A, B and P for each kind shown (screen direction of
 * the world vector, length from the kind's scale, clamped), their labels as layoutScene extras next to the
 * tips, the shafts as obstacles, and the scale legend in the bottom-right corner. Arrows whose vector is
 * zero or undetermined (a limit position) are left out; the legend says why.
 */
export function vectorOverlay(
  vectors: SceneVectors,
  pose: ScenePose | null,
  view: ViewTransform,
  measure: MeasureText,
): VectorOverlay {
  const t = vectors.text;
  const arrows: VectorArrow[] = [];
  const labels: ExtraLabel[] = [];
  const obstacles: Obstacle[] = [];
  const kinds: KindPlan[] = [
    ['v', vectors.velocity, vectors.velocityScale, THEME.velocity],
    ['a', vectors.acceleration, vectors.accelerationScale, THEME.acceleration],
  ];
  let anyClamped = false;
  for (const [kind, vs, scale, color] of kinds) {
    if (!pose || !vs || !scale) continue;
    for (const at of ['A', 'B', 'P'] as const) {
      const w = vs[at];
      const len = arrowLength(Math.hypot(w.x, w.y), scale.pxPerUnit);
      if (!len) continue;
      const from = frameToScreen(view, pose[at]);
      const m = Math.hypot(w.x, w.y);
      // Turned with a placed linkage's frame; screen y runs down, so the world's y component flips.
      const c = view.frame?.cos ?? 1;
      const s = view.frame?.sin ?? 0;
      const ux = (c * w.x - s * w.y) / m;
      const uy = -(s * w.x + c * w.y) / m;
      const to = { x: from.x + ux * len.lengthPx, y: from.y + uy * len.lengthPx };
      if (len.clamp !== 'none') anyClamped = true;
      arrows.push({ kind, at, from, to, clamp: len.clamp, color });
      obstacles.push({ kind: 'segment', a: from, b: to, halfWidth: STROKES.vector, weight: 2 });
      labels.push({
        id: `extra:${kind}${at}`,
        text: `${t.symbol[kind]}${at}`,
        font: 'regular',
        color,
        candidates: (width, height) => aroundTip(to, ux, uy, width, height),
      });
    }
  }
  const legend = placeLegend(legendRows(vectors, kinds, anyClamped), view, measure);
  return { arrows, legend, exclusions: legend ? [legend.box] : [], extras: { labels, obstacles } };
}

/** Draws the overlay's arrows (clamped ones dashed), under the labels. */
export function drawVectorArrows(ctx: Ctx, overlay: VectorOverlay): void {
  for (const a of overlay.arrows) drawArrow(ctx, a.from, a.to, a.color, a.clamp !== 'none');
}

/** Draws one arrow from → to (CSS pixels) in a colour, its shaft dashed when it is clamped (not to scale). */
export function drawArrow(ctx: Ctx, from: Px, to: Px, color: string, dashed: boolean): void {
  const dx = to.x - from.x;
  const dy = to.y - from.y;
  const len = Math.hypot(dx, dy);
  if (len < 1e-9) return;
  const ux = dx / len;
  const uy = dy / len;
  const head = Math.min(STROKES.vectorHead, len * 0.6);
  const hw = STROKES.vectorHeadWidth / 2;
  const base = { x: to.x - ux * head, y: to.y - uy * head };
  ctx.strokeStyle = color;
  ctx.fillStyle = color;
  ctx.lineWidth = STROKES.vector;
  ctx.lineCap = 'butt';
  ctx.setLineDash(dashed ? STROKES.vectorClampDash : []);
  ctx.beginPath();
  ctx.moveTo(from.x, from.y);
  ctx.lineTo(base.x, base.y);
  ctx.stroke();
  ctx.setLineDash([]);
  ctx.beginPath();
  ctx.moveTo(to.x, to.y);
  ctx.lineTo(base.x - uy * hw, base.y + ux * hw);
  ctx.lineTo(base.x + uy * hw, base.y - ux * hw);
  ctx.closePath();
  ctx.fill();
}

/** Draws the scale legend (the motion vectors' or the pin forces'): a translucent box with one bar and text per row. */
export function drawVectorLegend(ctx: Ctx, overlay: Pick<VectorOverlay, 'legend'>): void {
  const lg = overlay.legend;
  if (!lg) return;
  const { box } = lg;
  drawPanelBox(ctx, box, THEME.labelHalo, THEME.reference, 4);
  ctx.font = THEME.font;
  ctx.textBaseline = 'middle';
  ctx.textAlign = 'left';
  lg.rows.forEach((r, i) => {
    const y = box.y + LEGEND.pad + i * LEGEND.rowPx + (FONT_SIZES.canvas + 2 * LABEL_PAD_Y) / 2 - 1;
    let x = box.x + LEGEND.pad;
    if (r.barPx > 0) {
      drawArrow(ctx, { x, y }, { x: x + r.barPx, y }, r.color, r.dashed);
      x += r.barPx + LEGEND.gapPx;
    }
    ctx.fillStyle = r.barPx > 0 ? THEME.text : r.color;
    ctx.fillText(r.text, x, y);
  });
}
