import type { DrawContext } from '../canvas/drawContext';
import type { Obstacle } from '../canvas/labelPlacement';
import { candidatesAround } from '../canvas/labelPlacement';
import type { Px, ScreenRect } from '../canvas/rect';
import type { ViewTransform } from '../canvas/view';
import { frameToScreen } from '../canvas/view';
import { PI } from '../../solver/angles';
import { COLORS, STROKES } from '../theme/tokens';
import type { ArrowScale, LegendRow, VectorLegend, WorldVector } from './motionVectors';
import { LEGEND, arrowLength, drawArrow } from './motionVectors';
import type { ScenePose } from './scene';
import type { LocalPose } from './localPose';
import type { AppState } from '../state/appState';
import type { ExtraLabel, MeasureText, SceneExtras } from './sceneLayout';

/** The pins a force arrow is drawn at: the bearings O2 and O4 and the moving pins A and B. */
export type ForcePin = 'O2' | 'A' | 'B' | 'O4';

/** The pins in drawing order. */
export const FORCE_PINS: readonly ForcePin[] = ['O2', 'A', 'B', 'O4'];

/** Texts of the force overlay, already in the UI language. */
export interface ForceText {
  /** Each arrow's label, e.g. F12 at O2 (the force of link 1 on link 2). */
  label: Record<ForcePin, string>;
  /** The scale bar's row from the formatted value, e.g. "= 500 N". */
  bar: (value: string) => string;
  /** Row shown when every pin force is zero (no scale). */
  zero: string;
  /** Row shown when some arrow is clamped (drawn dashed, not to scale). */
  clamped: string;
  /** Row shown where the forces are undetermined (a limit position): no arrows then. */
  limit: string;
  formatValue: (x: number) => string;
}

/**
 * The pin forces to draw at this frame: a world vector (N, y up) at each pin (null: none to draw, at a limit
 * position or without a pose), the scale that stays put while the linkage moves, and the texts.
 */
export interface SceneForces {
  pins: Record<ForcePin, WorldVector> | null;
  scale: ArrowScale | null;
  /** True where the forces are undetermined (coupler and rocker in line). */
  limit: boolean;
  text: ForceText;
}

/**
 * What the app hands the canvas to draw pin forces with (a feature computes them; the canvas knows no forces):
 * the frame's state and pose to the forces to draw, or null for none. Called once per frame drawn.
 */
export type ForceLayer = (state: AppState, local: LocalPose) => SceneForces | null;

/** One force arrow in CSS pixels. */
export interface ForceArrow {
  at: ForcePin;
  from: Px;
  to: Px;
  clamped: boolean;
}

/** The force overlay to draw: arrows, the legend, and the labels and obstacles layoutScene places with the scene's. */
export interface ForceOverlay {
  arrows: ForceArrow[];
  legend: VectorLegend | null;
  /** The legend's box, for layoutScene's exclusions. */
  exclusions: ScreenRect[];
  extras: SceneExtras;
}

/** Turns from an arrow's direction: straight beyond its tip first, then turning away either side. */
const TIP_ROTATIONS = [0, 1, -1, 2, -2, 3, -3, 4, -4].map((k) => (k * PI) / 6);

/** The legend's rows: the scale bar (or the zero note), then the clamped and limit notes when they apply. */
function legendRows(forces: SceneForces, anyClamped: boolean): LegendRow[] {
  const t = forces.text;
  const color = COLORS.force;
  const rows: LegendRow[] = [];
  if (forces.scale) {
    rows.push({ barPx: forces.scale.barPx, color, text: t.bar(t.formatValue(forces.scale.value)), dashed: false });
  } else if (!forces.limit) {
    rows.push({ barPx: 0, color, text: t.zero, dashed: false });
  }
  if (anyClamped) rows.push({ barPx: 24, color: COLORS.textMuted, text: t.clamped, dashed: true });
  if (forces.limit) rows.push({ barPx: 0, color: COLORS.warning, text: t.limit, dashed: false });
  return rows;
}

/**
 * The legend's box, right-aligned in the bottom-right corner or, when another legend (the motion vectors') holds
 * that corner, just above it; null without rows.
 */
function placeLegend(
  rows: LegendRow[],
  view: ViewTransform,
  measure: MeasureText,
  below: ScreenRect | null,
): VectorLegend | null {
  if (rows.length === 0) return null;
  let w = 0;
  for (const r of rows) w = Math.max(w, (r.barPx > 0 ? r.barPx + LEGEND.gapPx : 0) + measure(r.text, 'regular'));
  const width = w + 2 * LEGEND.pad;
  const height = rows.length * LEGEND.rowPx + 2 * LEGEND.pad - 4;
  const bottom = below ? below.y - 4 : view.height - LEGEND.margin;
  return { box: { x: view.width - LEGEND.margin - width, y: bottom - height, width, height }, rows };
}

/**
 * Lays out the pin forces for a pose: at each pin an arrow along the force (its screen direction through the
 * view's frame, its length from the scale, clamped to the readable range and then dashed), its label as a
 * layoutScene extra beyond the tip, the shaft as an obstacle, and the scale legend in the bottom-right corner
 * (above the box `below` when given). Zero forces get no arrow; a limit position gets none, and the legend says why.
 */
export function forceOverlay(
  forces: SceneForces,
  pose: ScenePose | null,
  view: ViewTransform,
  measure: MeasureText,
  below: ScreenRect | null = null,
): ForceOverlay {
  const arrows: ForceArrow[] = [];
  const labels: ExtraLabel[] = [];
  const obstacles: Obstacle[] = [];
  const scale = forces.scale;
  const pins = forces.pins;
  let anyClamped = false;
  // Turned with a placed linkage's frame; screen y runs down, so the world's y component flips.
  const c = view.frame?.cos ?? 1;
  const s = view.frame?.sin ?? 0;
  if (pose && pins && scale) {
    for (const at of FORCE_PINS) {
      const f = pins[at];
      const m = Math.hypot(f.x, f.y);
      const len = arrowLength(m, scale.pxPerUnit);
      if (!len) continue;
      const from = frameToScreen(view, pose[at]);
      const ux = (c * f.x - s * f.y) / m;
      const uy = -(s * f.x + c * f.y) / m;
      const to = { x: from.x + ux * len.lengthPx, y: from.y + uy * len.lengthPx };
      const clamped = len.clamp !== 'none';
      if (clamped) anyClamped = true;
      arrows.push({ at, from, to, clamped });
      obstacles.push({ kind: 'segment', a: from, b: to, halfWidth: STROKES.vector, weight: 2 });
      labels.push({
        id: `extra:F${at}`,
        text: forces.text.label[at],
        font: 'regular',
        color: COLORS.force,
        candidates: (width, height) =>
          candidatesAround(to, { x: ux, y: uy }, TIP_ROTATIONS, [3, 9, 18], 0, width, height),
      });
    }
  }
  const legend = placeLegend(legendRows(forces, anyClamped), view, measure, below);
  return { arrows, legend, exclusions: legend ? [legend.box] : [], extras: { labels, obstacles } };
}

/** Draws the force arrows (clamped ones dashed), under the labels. */
export function drawForceArrows(ctx: DrawContext, overlay: ForceOverlay): void {
  for (const a of overlay.arrows) drawArrow(ctx, a.from, a.to, COLORS.force, a.clamped);
}
