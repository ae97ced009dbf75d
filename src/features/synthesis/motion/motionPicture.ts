/**
 * The Motion mode's canvas as a pure function of (context, picture, view): grid, the method's construction
 * (bisectors and circles, Burmester curves, Burmester points, the pole), the linkage at one pose with ghosts at
 * the others, and the poses with their handles; plus the handles' hit test. CSS pixels throughout.
 */
import { TWO_PI } from '../../../solver';
import type { Point } from '../../../solver';
import { toPlane } from '../../../synthesis';
import type { BurmesterPair, Pose } from '../../../synthesis';
import type { DrawContext } from '../../../shared/canvas/drawContext';
import { drawPanelBox } from '../../../shared/canvas/drawContext';
import { THEME } from '../../../shared/canvas/canvasTheme';
import type { Bounds, ViewTransform } from '../../../shared/canvas/view';
import { emptyBounds, extendBounds } from '../../../shared/canvas/view';
import type { PivotChoice } from '../../../shared/state/slices/synMotionSlice';
import type { MotionOutcome, ThreePoseOutcome } from './motionSolve';
import type { Px } from '../../../shared/canvas/rect';
import type { LabelPlacement, Obstacle } from '../../../shared/canvas/labelPlacement';
import { candidatesAround, placeLabels } from '../../../shared/canvas/labelPlacement';
import { placedJoints } from '../../../synthesis';
import { drawBackground, drawFourBar, drawLabel, drawMarker, drawPolyline, drawWorldCircle, px } from '../drawPlane';

/** Everything the Motion canvas draws. */
export interface MotionPicture {
  poses: Pose[];
  /** The pose the keyboard moves (0-based). */
  selected: number;
  outcome: MotionOutcome;
  pivotChoice: PivotChoice;
  /** Three poses: the pivots the designer placed (coupler frame for moving, plane for fixed). */
  pivots: readonly [Point, Point];
  /** Which pose the linkage is drawn at (0-based; the others get ghosts). */
  shownPose: number;
  /** Four poses: the dyad the curve slider is on, marked. */
  cursor: BurmesterPair | null;
  /** Legend texts of the Burmester curves. */
  legend: { centre: string; circle: string };
}

/** Length of a pose's turning handle, CSS pixels: long enough to aim, the same at any zoom. */
export const TURN_HANDLE_PX = 42;

/** What a pointer can grab: a pose's point, its turning handle, or a placed pivot (three poses). */
export type MotionHandle = { kind: 'point' | 'turn'; index: number } | { kind: 'pivot'; index: 0 | 1 };

const CENTRE_COLOR = THEME.instantCentre;
const CIRCLE_COLOR = THEME.angle;
const POSE_COLOR = THEME.trace;
const CONSTRUCTION_COLOR = THEME.deadCentre;

/** The placed pivots in the plane (three poses; the moving ones at pose 1). */
export function pivotPoints(pic: Pick<MotionPicture, 'poses' | 'pivotChoice' | 'pivots' | 'outcome'>): Point[] {
  if (pic.outcome.count !== 3) return [];
  return pic.pivotChoice === 'moving' ? pic.pivots.map((q) => toPlane(pic.poses[0], q)) : [...pic.pivots];
}

/** Where a pose's turning handle is drawn, CSS pixels. */
export function turnHandlePx(v: ViewTransform, pose: Pose): Px {
  const p = px(v, pose);
  return { x: p.x + TURN_HANDLE_PX * Math.cos(pose.angle), y: p.y - TURN_HANDLE_PX * Math.sin(pose.angle) };
}

/** The poses' spread: the largest distance of a pose's point from their centroid (1e-9 at least). */
export function poseSpread(poses: readonly Pose[]): number {
  const c = centroid(poses);
  return Math.max(1e-9, ...poses.map((p) => Math.hypot(p.x - c.x, p.y - c.y)));
}

/** Burmester points farther than this many times the nearest one's distance (or the spread) are left out of the fit. */
export const FAR_POINT_FACTOR = 10;

/**
 * Extends b by the points of a curve near c: those within twice the nearer of its nearest point's distance and the
 * poses' spread, so the stretch worth picking on is in view and the asymptotic arms are not.
 */
function extendByNear(b: Bounds, points: readonly Point[], c: Point, spread: number): void {
  const d = points.map((p) => Math.hypot(p.x - c.x, p.y - c.y));
  const reach = 2 * Math.max(spread, Math.min(...d));
  points.forEach((p, i) => {
    if (d[i] <= reach) extendBounds(b, p.x, p.y);
  });
}

/**
 * The box the view fits: the poses, the placed pivots and the chosen linkage's fixed pivots; (two poses) the pole;
 * (four poses) the stretch of each centre-point and circle-point curve nearest the poses, not their asymptotic arms;
 * (five poses) the Burmester points and (six or more) the least-squares dyads, with their circle points, but those
 * more than FAR_POINT_FACTOR times farther than the nearest one (or the spread).
 */
export function motionBounds(pic: MotionPicture): Bounds {
  const b = emptyBounds();
  for (const p of pic.poses) extendBounds(b, p.x, p.y);
  for (const p of pivotPoints(pic)) extendBounds(b, p.x, p.y);
  const chosen = pic.outcome.chosen;
  if (chosen) {
    const { O2, groundAngle, links } = chosen.design;
    extendBounds(b, O2.x, O2.y);
    extendBounds(b, O2.x + links.r1 * Math.cos(groundAngle), O2.y + links.r1 * Math.sin(groundAngle));
  }
  if (pic.outcome.count === 2 && pic.outcome.pole) extendBounds(b, pic.outcome.pole.x, pic.outcome.pole.y);
  const c = centroid(pic.poses);
  const spread = poseSpread(pic.poses);
  if (pic.outcome.count === 4) {
    for (const curve of pic.outcome.curves) {
      extendByNear(
        b,
        curve.map((d) => d.center),
        c,
        spread,
      );
      extendByNear(
        b,
        curve.map((d) => toPlane(pic.poses[0], d.circle)),
        c,
        spread,
      );
    }
  }
  const marked = pic.outcome.count === 5 ? pic.outcome.points : pic.outcome.count === 6 ? pic.outcome.dyads : [];
  if (marked.length) {
    const points = marked.flatMap((d) => [d.center, toPlane(pic.poses[0], d.circle)]);
    const d = points.map((p) => Math.hypot(p.x - c.x, p.y - c.y));
    const reach = FAR_POINT_FACTOR * Math.max(spread, Math.min(...d));
    points.forEach((p, i) => {
      if (d[i] <= reach) extendBounds(b, p.x, p.y);
    });
  }
  return b;
}

/** The mean of the poses' points. */
export function centroid(poses: readonly Pose[]): Point {
  const n = poses.length;
  return { x: poses.reduce((a, p) => a + p.x, 0) / n, y: poses.reduce((a, p) => a + p.y, 0) / n };
}

/** The index of the sample whose centre is nearest to at (0 when there are none). */
export function nearestSample(samples: readonly BurmesterPair[], at: Point): number {
  let best = 0;
  let bestD = Infinity;
  samples.forEach((d, i) => {
    const dist = Math.hypot(d.center.x - at.x, d.center.y - at.y);
    if (dist < bestD) {
      bestD = dist;
      best = i;
    }
  });
  return best;
}

/** The handle within radius CSS pixels of at: a turning handle first, then a pose point, then a pivot; else null. */
export function handleAt(pic: MotionPicture, v: ViewTransform, at: Px, radius: number): MotionHandle | null {
  let best: MotionHandle | null = null;
  let bestD = radius;
  const consider = (h: MotionHandle, p: Px, bias: number) => {
    const d = Math.hypot(p.x - at.x, p.y - at.y) - bias;
    if (d <= bestD) {
      bestD = d;
      best = h;
    }
  };
  pivotPoints(pic).forEach((p, i) => consider({ kind: 'pivot', index: i as 0 | 1 }, px(v, p), 0));
  // Small biases settle ties: a pose's point over a pivot under it, its handle over both.
  pic.poses.forEach((p, i) => consider({ kind: 'point', index: i }, px(v, p), 0.5));
  pic.poses.forEach((p, i) => consider({ kind: 'turn', index: i }, turnHandlePx(v, p), 1));
  return best;
}

/** A perpendicular bisector, dashed, from the chord's midpoint through the centre and a little beyond. */
function drawBisector(ctx: DrawContext, v: ViewTransform, a: Point, b: Point, centre: Point): void {
  const m = { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
  const beyond = { x: centre.x + (centre.x - m.x) * 0.15, y: centre.y + (centre.y - m.y) * 0.15 };
  drawPolyline(ctx, v, [a, b], CONSTRUCTION_COLOR, 1);
  drawPolyline(ctx, v, [m, beyond], CONSTRUCTION_COLOR, 1, [5, 4]);
}

function drawConstruction(ctx: DrawContext, v: ViewTransform, construction: ThreePoseOutcome['construction']): void {
  for (const c of construction) {
    const [p1, p2, p3] = c.points;
    drawWorldCircle(ctx, v, c.centre, Math.hypot(p1.x - c.centre.x, p1.y - c.centre.y), THEME.reference, [2, 3]);
    drawBisector(ctx, v, p1, p2, c.centre);
    drawBisector(ctx, v, p2, p3, c.centre);
    for (const p of c.points) drawMarker(ctx, v, p, 'ring', CONSTRUCTION_COLOR, 3);
    drawMarker(ctx, v, c.centre, 'cross', CONSTRUCTION_COLOR, 5);
  }
}

/** A dyad: its centre (fixed pivot) and its circle point at pose 1, joined (numbered later, over the linkage). */
function drawDyad(ctx: DrawContext, v: ViewTransform, pose1: Pose, d: BurmesterPair, shape: 'dot' | 'diamond'): void {
  const circle = toPlane(pose1, d.circle);
  drawPolyline(ctx, v, [d.center, circle], THEME.text, 1, [3, 3]);
  drawMarker(ctx, v, d.center, shape, CENTRE_COLOR, 5);
  drawMarker(ctx, v, circle, shape === 'dot' ? 'ring' : 'hollowDiamond', CIRCLE_COLOR, 5);
}

/** The numbered dyads (five poses: the Burmester points; six or more: the best-fit dyads), as the list names them. */
function numberedDyads(pic: MotionPicture): BurmesterPair[] {
  const o = pic.outcome;
  return o.count === 5 ? o.points : o.count === 6 ? o.dyads : [];
}

/** Label text height (CSS pixels) for the placer: the canvas font's size and a pixel of halo each side. */
const POINT_LABEL_HEIGHT = 16;
/** Eight directions 45° apart, up-right first (where drawLabel used to put them), turning counter-clockwise. */
const POINT_LABEL_TURNS = [0, 1, 2, 3, 4, 5, 6, 7].map((k) => (-k * TWO_PI) / 8);
const POINT_LABEL_START = { x: Math.SQRT1_2, y: -Math.SQRT1_2 };

/**
 * Where the Burmester points' numbers go (CSS pixels): beside each centre and circle point, clear of the other
 * numbers and, as far as a spot allows, of the linkage drawn (its links and joints, ghosts too), the poses and the
 * dyads' markers (the shared label placer). A number with no free spot in the view is dropped. Ids `c1`, `m1`, …:
 * centre and circle point of dyad 1.
 */
export function pointLabelPlacements(
  ctx: Pick<DrawContext, 'measureText' | 'font'>,
  pic: MotionPicture,
  v: ViewTransform,
): { placements: LabelPlacement<string>[]; texts: Map<string, string> } {
  const dyads = numberedDyads(pic);
  const texts = new Map<string, string>();
  if (dyads.length === 0) return { placements: [], texts };
  ctx.font = THEME.font;
  const obstacles: Obstacle[] = [];
  const box = (p: Px, r: number, weight: number) =>
    obstacles.push({ kind: 'rect', rect: { x: p.x - r, y: p.y - r, width: 2 * r, height: 2 * r }, weight });
  const chosen = pic.outcome.chosen;
  if (chosen) {
    chosen.theta2.forEach((t, i) => {
      const j = placedJoints(chosen.design, t);
      if (!j) return;
      const shown = i === Math.min(pic.shownPose, chosen.theta2.length - 1);
      const [O2, A, B, O4, P] = [j.O2, j.A, j.B, j.O4, j.P].map((q) => px(v, q));
      const weight = shown ? 4 : 1;
      for (const [a, b] of [
        [O2, A],
        [A, B],
        [B, O4],
        [A, P],
        [B, P],
      ] as const)
        obstacles.push({ kind: 'segment', a, b, halfWidth: shown ? 5 : 2, weight });
      for (const q of [O2, A, B, O4, P]) box(q, 7, weight * 2);
      // The ground symbols under the fixed pivots (drawn with the shown pose).
      if (shown)
        for (const q of [O2, O4])
          obstacles.push({ kind: 'rect', rect: { x: q.x - 10, y: q.y, width: 20, height: 16 }, weight: 4 });
    });
  }
  for (const pose of pic.poses) {
    const p = px(v, pose);
    box(p, 8, 3);
    obstacles.push({ kind: 'segment', a: p, b: turnHandlePx(v, pose), halfWidth: 3, weight: 2 });
  }
  const requests = dyads.flatMap((d, i) => {
    const text = String(i + 1);
    const width = ctx.measureText(text).width + 4;
    return (
      [
        ['c', d.center],
        ['m', toPlane(pic.poses[0], d.circle)],
      ] as const
    ).map(([kind, at]) => {
      const p = px(v, at);
      box(p, 6, 3);
      const id = `${kind}${i + 1}`;
      texts.set(id, text);
      const candidates = candidatesAround(
        p,
        POINT_LABEL_START,
        POINT_LABEL_TURNS,
        [2, 8, 16],
        5,
        width,
        POINT_LABEL_HEIGHT,
      );
      return { id, width, height: POINT_LABEL_HEIGHT, candidates };
    });
  });
  const bounds = { x: 0, y: 0, width: v.width, height: v.height };
  return { placements: placeLabels(requests, bounds, [], obstacles).placed, texts };
}

/** The Burmester points' numbers, over everything else (pointLabelPlacements). */
function drawPointLabels(ctx: DrawContext, v: ViewTransform, pic: MotionPicture): void {
  const { placements, texts } = pointLabelPlacements(ctx, pic, v);
  ctx.font = THEME.font;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.lineWidth = 3;
  for (const l of placements) {
    const text = texts.get(l.id) ?? '';
    ctx.strokeStyle = THEME.labelHalo;
    ctx.strokeText(text, l.centre.x, l.centre.y);
    ctx.fillStyle = THEME.text;
    ctx.fillText(text, l.centre.x, l.centre.y);
  }
}

function drawLegend(ctx: DrawContext, legend: MotionPicture['legend']): void {
  ctx.font = THEME.font;
  const rows = [
    [legend.centre, CENTRE_COLOR],
    [legend.circle, CIRCLE_COLOR],
  ] as const;
  const width = Math.max(...rows.map(([t]) => ctx.measureText(t).width)) + 34;
  drawPanelBox(ctx, { x: 8, y: 8, width, height: 44 }, THEME.background, THEME.grid, 4);
  rows.forEach(([text, color], i) => {
    const y = 21 + i * 18;
    ctx.strokeStyle = color;
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.moveTo(14, y);
    ctx.lineTo(32, y);
    ctx.stroke();
    ctx.fillStyle = THEME.text;
    ctx.textAlign = 'left';
    ctx.textBaseline = 'middle';
    ctx.fillText(text, 38, y);
  });
}

/** The method's own marks under the linkage. */
function drawMethod(ctx: DrawContext, v: ViewTransform, pic: MotionPicture): void {
  const o = pic.outcome;
  if (o.count === 3) drawConstruction(ctx, v, o.construction);
  if (o.count === 4) {
    for (const curve of o.curves) {
      drawPolyline(
        ctx,
        v,
        curve.map((d) => d.center),
        CENTRE_COLOR,
        2,
      );
      drawPolyline(
        ctx,
        v,
        curve.map((d) => toPlane(pic.poses[0], d.circle)),
        CIRCLE_COLOR,
        1.5,
      );
    }
    for (const d of o.dyads) drawDyad(ctx, v, pic.poses[0], d, 'dot');
    if (pic.cursor) drawMarker(ctx, v, pic.cursor.center, 'ring', THEME.text, 8);
  }
  // Numbered as the four-bar list names them ("points 1 + 3"), over the linkage (drawPointLabels).
  for (const d of numberedDyads(pic)) drawDyad(ctx, v, pic.poses[0], d, 'diamond');
  if (o.count === 2 && o.pole) {
    drawWorldCircle(ctx, v, o.pole, o.rocker, THEME.reference, [2, 3]);
    drawMarker(ctx, v, o.pole, 'cross', CONSTRUCTION_COLOR, 5);
  }
}

/** The poses: point, direction line to the turning handle, number; the selected one ringed. */
function drawPoses(ctx: DrawContext, v: ViewTransform, pic: MotionPicture): void {
  pic.poses.forEach((pose, i) => {
    const p = px(v, pose);
    const h = turnHandlePx(v, pose);
    ctx.strokeStyle = POSE_COLOR;
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.moveTo(p.x, p.y);
    ctx.lineTo(h.x, h.y);
    ctx.stroke();
    ctx.fillStyle = THEME.background;
    ctx.beginPath();
    ctx.arc(h.x, h.y, 5, 0, TWO_PI);
    ctx.fill();
    ctx.stroke();
    drawMarker(ctx, v, pose, 'dot', POSE_COLOR, 6);
    if (i === pic.selected) {
      ctx.strokeStyle = THEME.text;
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.arc(p.x, p.y, 10, 0, TWO_PI);
      ctx.stroke();
    }
    drawLabel(ctx, v, pose, String(i + 1), -16, 12);
  });
}

/** Draws the whole Motion canvas. */
export function drawMotion(ctx: DrawContext, pic: MotionPicture, v: ViewTransform): void {
  drawBackground(ctx, v);
  drawMethod(ctx, v, pic);
  const chosen = pic.outcome.chosen;
  if (chosen) {
    chosen.theta2.forEach((t, i) => {
      if (i !== pic.shownPose) drawFourBar(ctx, v, chosen.design, t, true);
    });
    const shown = chosen.theta2[Math.min(pic.shownPose, chosen.theta2.length - 1)];
    drawFourBar(ctx, v, chosen.design, shown);
  }
  pivotPoints(pic).forEach((p) => drawMarker(ctx, v, p, 'ring', THEME.text, 7));
  drawPoses(ctx, v, pic);
  drawPointLabels(ctx, v, pic);
  if (pic.outcome.count === 4) drawLegend(ctx, pic.legend);
}
