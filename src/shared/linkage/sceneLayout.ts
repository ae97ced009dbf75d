import { PI, TWO_PI, angleDiff, radToDeg } from '../../solver/angles';
import { FONT_SIZES, STROKES } from '../theme/tokens';
import type { DesignLayout } from './designOverlay';
import { designLabels, layoutDesign, muOutsideBand } from './designOverlay';
import type { LabelRequest, Obstacle } from '../canvas/labelPlacement';
import { candidatesAround, placeLabels } from '../canvas/labelPlacement';
import type { Px, ScreenRect } from '../canvas/rect';
import { halfExtentAlong, rectAround } from '../canvas/rect';
import type { LinkageScene, ScenePose, SceneText } from './scene';
import { THEME } from '../canvas/canvasTheme';
import type { ViewTransform } from '../canvas/view';
import { frameAngle, frameToScreen, gridLines } from '../canvas/view';

/** Every text the canvas may draw, in placement order (most important first). */
export type LabelId =
  | 'warning'
  | 'grid'
  | 'O2'
  | 'O4'
  | 'A'
  | 'B'
  | 'P'
  | 'theta2'
  | 'theta3'
  | 'theta4'
  | 'mu'
  | 'r2'
  | 'r3'
  | 'r4'
  | 'r1'
  | 'swing'
  | 'I13'
  | 'I24'
  | ExtraLabelId;

/** Id of a label an overlay adds through SceneExtras (e.g. 'extra:vP'). */
export type ExtraLabelId = `extra:${string}`;

/** The two label fonts: THEME.font (FONT_SIZES.canvas) and THEME.fontBold (FONT_SIZES.canvasBold). */
export type LabelFont = 'regular' | 'bold';

/** Width in CSS pixels of text set in a label font (ctx.measureText on screen; a fixed model in tests). */
export type MeasureText = (text: string, font: LabelFont) => number;

/** A placed canvas label: text, font and colour, centre and box in CSS pixels. */
export interface SceneLabel {
  id: Exclude<LabelId, 'warning'>;
  text: string;
  font: LabelFont;
  color: string;
  centre: Px;
  box: ScreenRect;
}

/** An angle arc: centre (CSS pixels), radius (CSS pixels), from and to in world radians (counter-clockwise). */
export interface SceneArc {
  centre: Px;
  radiusPx: number;
  fromRad: number;
  toRad: number;
  color: string;
}

/** The can't-assemble message box (CSS pixels) and its one or two lines. */
export interface WarningBox {
  box: ScreenRect;
  title: string;
  detail: string | null;
}

/** A label an overlay asks layoutScene to place: text, font, colour and its candidate centres for a box size. */
export interface ExtraLabel {
  id: ExtraLabelId;
  text: string;
  font: LabelFont;
  color: string;
  candidates: (width: number, height: number) => Px[];
}

/** Labels and obstacles an overlay adds (the motion vectors): placed after the scene's own labels, avoided by all. */
export interface SceneExtras {
  labels: readonly ExtraLabel[];
  obstacles: readonly Obstacle[];
}

/** Screen positions of the joints: A is the crank pin at theta2 even with no pose; B and P need a pose. */
export interface SceneJoints {
  O2: Px;
  O4: Px;
  A: Px;
  B: Px | null;
  P: Px | null;
}

/** Everything drawLinkage places on the canvas: joints, angle arcs, labels that do not overlap, the warning. */
export interface SceneLayout {
  joints: SceneJoints;
  arcs: SceneArc[];
  /** Dashed zero-angle references: segments in CSS pixels. */
  references: [Px, Px][];
  labels: SceneLabel[];
  warning: WarningBox | null;
  /** Labels that found no free spot (off-canvas joints, or a crowded tiny linkage). */
  dropped: LabelId[];
  /** The design overlay in CSS pixels; null when the scene has none. */
  design: DesignLayout | null;
}

/** Padding (CSS pixels) around a label's text inside its box; covers the white halo. */
export const LABEL_PAD_X = 2;
export const LABEL_PAD_Y = 2;

/** Geometry of the warning box (CSS pixels): side padding, heights for one and two lines, text baselines from its top. */
export const WARNING_BOX = {
  padX: 14,
  margin: 8,
  top: 12,
  heightOneLine: 32,
  heightTwoLines: 50,
  titleY: 16,
  detailY: 35,
} as const;

/** Radii (CSS pixels) of the angle arcs at O2 (theta2), A (theta3), O4 (theta4) and B (mu). */
export const ARC_RADII = { theta2: 30, theta3: 26, theta4: 34, mu: 22 } as const;

/** Length (CSS pixels) of the dashed zero-angle references at A and O4. */
export const REFERENCE_LENGTH_PX = 46;

/** Target spacing of grid lines in CSS pixels. */
export const GRID_TARGET_PX = 64;

/**
 * Obstacle weight of a link bar: more than a label crossing an arc, a reference line and a plate edge together,
 * so a label goes over a bar only when no other free spot is left (an angle text over the coupler read as part of it).
 */
const LINK_BAR_WEIGHT = 10;

const FONT_PX: Record<LabelFont, number> = { regular: FONT_SIZES.canvas, bold: FONT_SIZES.canvasBold };
const ROTATIONS = [0, 1, -1, 2, -2, 3, -3, 4, -4, 5, -5, 6].map((k) => (k * PI) / 6);

function px(v: ViewTransform, p: { x: number; y: number }): Px {
  return frameToScreen(v, p);
}

/** Unit vector from the others' directions, pointing away from them all; straight up when they cancel. */
function awayFrom(p: Px, others: readonly Px[]): Px {
  let dx = 0;
  let dy = 0;
  for (const o of others) {
    const ox = p.x - o.x;
    const oy = p.y - o.y;
    const d = Math.hypot(ox, oy);
    if (d < 1e-9) continue;
    dx += ox / d;
    dy += oy / d;
  }
  const d = Math.hypot(dx, dy);
  return d < 1e-6 ? { x: 0, y: -1 } : { x: dx / d, y: dy / d };
}

/** Centres around a point: rotations of the preferred direction, at growing gaps beyond a clearance. */
function aroundPoint(p: Px, preferred: Px, clearancePx: number, width: number, height: number): Px[] {
  return candidatesAround(p, preferred, ROTATIONS, [2, 7, 14, 24], clearancePx, width, height);
}

/** Centres beside a segment: along it (middle first), on the preferred side first, at growing gaps. */
function besideSegment(a: Px, b: Px, awayFromPt: Px, clearancePx: number, width: number, height: number): Px[] {
  const len = Math.hypot(b.x - a.x, b.y - a.y);
  let nx = len > 1e-9 ? -(b.y - a.y) / len : 0;
  let ny = len > 1e-9 ? (b.x - a.x) / len : -1;
  const mx = (a.x + b.x) / 2;
  const my = (a.y + b.y) / 2;
  if (nx * (awayFromPt.x - mx) + ny * (awayFromPt.y - my) > 0) {
    nx = -nx;
    ny = -ny;
  }
  const out: Px[] = [];
  for (const gap of [2, 8, 16, 28]) {
    for (const t of [0.5, 0.35, 0.65, 0.2, 0.8]) {
      for (const side of [1, -1]) {
        const ux = nx * side;
        const uy = ny * side;
        const d = clearancePx + gap + halfExtentAlong(ux, uy, width, height);
        out.push({ x: a.x + (b.x - a.x) * t + ux * d, y: a.y + (b.y - a.y) * t + uy * d });
      }
    }
  }
  return out;
}

/** Centres outside an arc: at its middle first, then along it, then beyond its ends, at growing gaps. */
function besideArc(arc: SceneArc, width: number, height: number): Px[] {
  const sweep = arc.toRad - arc.fromRad;
  const angles = [0.5, 0.3, 0.7, 0.15, 0.85, 0, 1].map((f) => arc.fromRad + sweep * f);
  const mid = arc.fromRad + sweep / 2;
  // Then round the rest of the circle, so a crowded arc still finds a spot off the link bars.
  for (const k of [1, -1, 2, -2, 3, -3, 4, -4, 5, -5, 6, -6, 7, -7])
    angles.push(mid + (k * PI) / 8 + (Math.sign(k) * Math.abs(sweep)) / 2);
  const out: Px[] = [];
  for (const gap of [3, 9, 18]) {
    for (const phi of angles) {
      const ux = Math.cos(phi);
      const uy = -Math.sin(phi);
      const d = arc.radiusPx + gap + halfExtentAlong(ux, uy, width, height);
      out.push({ x: arc.centre.x + ux * d, y: arc.centre.y + uy * d });
    }
  }
  return out;
}

function arcObstacles(arc: SceneArc, weight: number, owner: LabelId): Obstacle[] {
  const out: Obstacle[] = [];
  const n = 8;
  let prev: Px | null = null;
  for (let i = 0; i <= n; i++) {
    const phi = arc.fromRad + ((arc.toRad - arc.fromRad) * i) / n;
    const p = { x: arc.centre.x + arc.radiusPx * Math.cos(phi), y: arc.centre.y - arc.radiusPx * Math.sin(phi) };
    if (prev) out.push({ kind: 'segment', a: prev, b: p, halfWidth: 1, weight, owner });
    prev = p;
  }
  return out;
}

function jointBox(p: Px, radiusPx: number, weight: number): Obstacle {
  return { kind: 'rect', rect: rectAround(p, 2 * radiusPx + 2, 2 * radiusPx + 2), weight };
}

/** The ground-pivot symbol under a pivot (triangle, base line and hatching), as drawLinkage draws it. */
export function groundSymbolRect(p: Px): ScreenRect {
  return { x: p.x - 19, y: p.y, width: 38, height: 24.5 };
}

/** Arcs of the angle annotations of a pose: theta2 at O2, theta3 at A, theta4 at O4, mu at B. */
function poseArcs(
  pose: ScenePose,
  j: { O2: Px; A: Px; B: Px; O4: Px },
  g = 0,
): Record<'theta2' | 'theta3' | 'theta4' | 'mu', SceneArc> {
  const t2 = angleDiff(pose.theta2, 0);
  const t2Pos = t2 >= 0 ? t2 : TWO_PI + t2;
  const fromB = g + pose.theta3 + PI;
  return {
    theta2: { centre: j.O2, radiusPx: ARC_RADII.theta2, fromRad: g, toRad: g + t2Pos, color: THEME.crank },
    theta3: {
      centre: j.A,
      radiusPx: ARC_RADII.theta3,
      fromRad: g,
      toRad: g + angleDiff(pose.theta3, 0),
      color: THEME.coupler,
    },
    theta4: {
      centre: j.O4,
      radiusPx: ARC_RADII.theta4,
      fromRad: g,
      toRad: g + angleDiff(pose.theta4, 0),
      color: THEME.rocker,
    },
    mu: {
      centre: j.B,
      radiusPx: ARC_RADII.mu,
      fromRad: fromB,
      toRad: fromB + angleDiff(g + pose.theta4 + PI, fromB),
      color: THEME.angle,
    },
  };
}

/** Labels to place and what each says: add measures a label and asks its candidate centres for that size. */
interface LabelCollector {
  requests: LabelRequest<LabelId>[];
  meta: Map<LabelId, { text: string; font: LabelFont; color: string }>;
  add: (id: LabelId, text: string, font: LabelFont, color: string, make: (w: number, h: number) => Px[]) => void;
}

function labelCollector(measure: MeasureText): LabelCollector {
  const requests: LabelRequest<LabelId>[] = [];
  const meta: LabelCollector['meta'] = new Map();
  const add: LabelCollector['add'] = (id, text, font, color, make) => {
    const width = measure(text, font) + 2 * LABEL_PAD_X;
    const height = FONT_PX[font] + 2 * LABEL_PAD_Y;
    meta.set(id, { text, font, color });
    requests.push({ id, width, height, candidates: make(width, height) });
  };
  return { requests, meta, add };
}

/** The warning box's request (top centre, or left, or under each exclusion; never dropped) and its first box. */
function warningRequest(
  text: SceneText,
  view: ViewTransform,
  measure: MeasureText,
  exclusions: readonly ScreenRect[],
): { request: LabelRequest<LabelId>; warning: WarningBox } | null {
  if (!text.warning) return null;
  const w = Math.min(
    view.width - 2 * WARNING_BOX.margin,
    Math.max(measure(text.warning, 'bold'), text.warningDetail ? measure(text.warningDetail, 'regular') : 0) +
      2 * WARNING_BOX.padX,
  );
  const h = text.warningDetail ? WARNING_BOX.heightTwoLines : WARNING_BOX.heightOneLine;
  const xs = [view.width / 2, WARNING_BOX.margin + w / 2];
  const ys = [WARNING_BOX.top, ...exclusions.map((e) => e.y + e.height + 6)].map((y) => y + h / 2);
  const candidates = ys.flatMap((y) => xs.map((x) => ({ x, y })));
  return {
    request: { id: 'warning', width: w, height: h, candidates, required: true },
    warning: { box: rectAround(candidates[0], w, h), title: text.warning, detail: text.warningDetail },
  };
}

/** The grid spacing label's candidates: the four corners, bottom left first. */
function gridLabelCandidates(view: ViewTransform, w: number, h: number): Px[] {
  return [
    { x: 8 + w / 2, y: view.height - 6 - h / 2 },
    { x: view.width - 8 - w / 2, y: view.height - 6 - h / 2 },
    { x: 8 + w / 2, y: 6 + h / 2 },
    { x: view.width - 8 - w / 2, y: 6 + h / 2 },
  ];
}

/** The arcs drawn, reference lines and labels of θ2, θ3, θ4 and μ (μ in the warning colour outside the design band). */
function addAngleLabels(
  scene: LinkageScene,
  pose: ScenePose,
  j: { O2: Px; A: Px; B: Px; O4: Px },
  labels: LabelCollector,
  obstacles: Obstacle[],
  g: number,
): { arcs: SceneArc[]; references: [Px, Px][] } {
  const t = scene.text;
  const { A, O4 } = j;
  const deg = (r: number) => t.formatAngle(radToDeg(r));
  // The arcs turn with a placed linkage's frame (g); their texts are the angles from its ground line.
  const a = poseArcs(pose, j, g);
  const arcs: SceneArc[] = [];
  const ref = { x: REFERENCE_LENGTH_PX * Math.cos(g), y: -REFERENCE_LENGTH_PX * Math.sin(g) };
  const references: [Px, Px][] = [
    [A, { x: A.x + ref.x, y: A.y + ref.y }],
    [O4, { x: O4.x + ref.x, y: O4.y + ref.y }],
  ];
  const texts = {
    theta2: `θ2 ${deg(a.theta2.toRad - g)}`,
    theta3: `θ3 ${deg(a.theta3.toRad - g)}`,
    theta4: `θ4 ${deg(a.theta4.toRad - g)}`,
    mu: `μ ${deg(pose.mu)}`,
  };
  for (const id of ['theta2', 'theta3', 'theta4', 'mu'] as const) {
    const arc = a[id];
    if (Math.abs(arc.toRad - arc.fromRad) < 1e-9) continue;
    arcs.push(arc);
    obstacles.push(...arcObstacles(arc, 1, id));
    const color = id === 'mu' && muOutsideBand(scene.design, pose.mu) ? THEME.warning : arc.color;
    labels.add(id, texts[id], 'regular', color, (w, h) => besideArc(arc, w, h));
  }
  for (const [p, q] of references) obstacles.push({ kind: 'segment', a: p, b: q, halfWidth: 1, weight: 1 });
  return { arcs, references };
}

/** The labels of B and P, and the obstacles of B, P, the coupler and the rocker. */
function addPoseLabels(
  j: { A: Px; B: Px; P: Px; O4: Px },
  t: SceneText,
  labels: LabelCollector,
  obstacles: Obstacle[],
): void {
  const { A, B, P, O4 } = j;
  const jointClear = STROKES.jointRadius + 2;
  labels.add('B', t.B, 'bold', THEME.text, (w, h) => aroundPoint(B, awayFrom(B, [A, O4]), jointClear, w, h));
  labels.add('P', t.P, 'bold', THEME.couplerPoint, (w, h) =>
    aroundPoint(P, awayFrom(P, [A, B]), STROKES.couplerPointRadius + 2, w, h),
  );
  obstacles.push(
    jointBox(B, STROKES.jointRadius, 4),
    jointBox(P, STROKES.couplerPointRadius, 4),
    { kind: 'segment', a: A, b: B, halfWidth: STROKES.link / 2, weight: LINK_BAR_WEIGHT, owner: 'r3' },
    { kind: 'segment', a: B, b: O4, halfWidth: STROKES.link / 2, weight: LINK_BAR_WEIGHT, owner: 'r4' },
    { kind: 'segment', a: A, b: P, halfWidth: STROKES.couplerPlate, weight: 1 },
    { kind: 'segment', a: B, b: P, halfWidth: STROKES.couplerPlate, weight: 1 },
  );
}

/** The link labels r2, r3 and r4 beside their links (the angle labels are placed before them). */
function addLinkLabels(
  pose: ScenePose,
  j: { O2: Px; A: Px; B: Px; P: Px; O4: Px },
  labels: LabelCollector,
  g: number,
): void {
  const { O2, A, B, P, O4 } = j;
  // The coupler label goes away from P when P is off the line AB, else away from O2.
  const pOffLine =
    Math.abs((B.x - A.x) * (P.y - A.y) - (B.y - A.y) * (P.x - A.x)) > 4 * Math.hypot(B.x - A.x, B.y - A.y);
  const t2 = angleDiff(pose.theta2, 0);
  const t2Half = g + (t2 >= 0 ? t2 : TWO_PI + t2) / 2;
  const arcMid = { x: O2.x + 30 * Math.cos(t2Half), y: O2.y - 30 * Math.sin(t2Half) };
  const linkClear = STROKES.link / 2;
  labels.add('r2', 'r2', 'regular', THEME.crank, (w, h) => besideSegment(O2, A, arcMid, linkClear, w, h));
  labels.add('r3', 'r3', 'regular', THEME.coupler, (w, h) => besideSegment(A, B, pOffLine ? P : O2, linkClear, w, h));
  labels.add('r4', 'r4', 'regular', THEME.rocker, (w, h) => besideSegment(B, O4, A, linkClear, w, h));
}

/** The order labels are placed in: the warning, the grid label, the joints, angles and links, the design overlay; extras after. */
const LABEL_ORDER: readonly LabelId[] = [
  'warning',
  'grid',
  'O2',
  'O4',
  'A',
  'B',
  'P',
  'theta2',
  'theta3',
  'theta4',
  'mu',
  'r2',
  'r3',
  'r4',
  'r1',
  'swing',
  'I13',
  'I24',
];

/** The rank of a label in LABEL_ORDER; labels not listed (the extras) come last, in their order. */
function labelRank(id: LabelId): number {
  const k = LABEL_ORDER.indexOf(id);
  return k >= 0 ? k : LABEL_ORDER.length;
}

/** What the labels avoid before the pose: the pivots, the crank pin, the ground symbols, the frame and the crank. */
function groundObstacles(O2: Px, O4: Px, A: Px): Obstacle[] {
  return [
    jointBox(O2, STROKES.pivotRadius, 4),
    jointBox(O4, STROKES.pivotRadius, 4),
    jointBox(A, STROKES.jointRadius, 4),
    { kind: 'rect', rect: groundSymbolRect(O2), weight: 2 },
    { kind: 'rect', rect: groundSymbolRect(O4), weight: 2 },
    { kind: 'segment', a: O2, b: O4, halfWidth: STROKES.ground, weight: 1, owner: 'r1' },
    { kind: 'segment', a: O2, b: A, halfWidth: STROKES.link / 2, weight: LINK_BAR_WEIGHT, owner: 'r2' },
  ];
}

/** The placed labels with their texts, and the warning box moved to where it was placed. */
function sceneLabels(
  placed: readonly { id: LabelId; centre: Px; box: ScreenRect }[],
  meta: LabelCollector['meta'],
  warning: WarningBox | null,
): { labels: SceneLabel[]; warning: WarningBox | null } {
  const labels: SceneLabel[] = [];
  let placedWarning = warning;
  for (const p of placed) {
    if (p.id === 'warning') {
      if (placedWarning) placedWarning = { ...placedWarning, box: p.box };
      continue;
    }
    const m = meta.get(p.id)!;
    labels.push({ id: p.id, text: m.text, font: m.font, color: m.color, centre: p.centre, box: p.box });
  }
  return { labels, warning: placedWarning };
}

/**
 * Lays out the canvas: joint positions, angle arcs and every label, placed so that no two labels overlap and
 * none overlaps an exclusion rectangle (the zoom buttons: canvasToolsRect) or leaves the canvas. Labels are
 * placed in LabelId order; one with no free spot is dropped and listed. measure gives text widths in CSS pixels.
 * extras (an overlay's labels and obstacles) are placed last, in their order, and their obstacles avoided by every label.
 */
export function layoutScene(
  scene: LinkageScene,
  view: ViewTransform,
  measure: MeasureText,
  exclusions: readonly ScreenRect[] = [],
  extras: SceneExtras | null = null,
): SceneLayout {
  const v = view;
  const l = scene.linkage;
  const t = scene.text;
  const bounds: ScreenRect = { x: 0, y: 0, width: v.width, height: v.height };
  const pose = scene.pose;
  const O2 = px(v, { x: 0, y: 0 });
  const O4 = px(v, { x: l.r1, y: 0 });
  const A = pose ? px(v, pose.A) : px(v, { x: l.r2 * Math.cos(scene.theta2), y: l.r2 * Math.sin(scene.theta2) });
  const B = pose ? px(v, pose.B) : null;
  const P = pose ? px(v, pose.P) : null;
  const joints: SceneJoints = { O2, O4, A, B, P };

  const labels = labelCollector(measure);
  const warned = warningRequest(t, v, measure, exclusions);
  if (warned) labels.requests.push(warned.request);
  const grid = scene.showGrid ? gridLines(v, GRID_TARGET_PX) : null;
  if (grid) {
    labels.add('grid', t.gridSpacing(t.formatLength(grid.step)), 'regular', THEME.gridText, (w, h) =>
      gridLabelCandidates(v, w, h),
    );
  }

  const jointClear = STROKES.jointRadius + 2;
  const pivotClear = STROKES.pivotRadius + 2;
  labels.add('O2', t.O2, 'bold', THEME.text, (w, h) =>
    aroundPoint(O2, awayFrom(O2, [A, O4, { x: O2.x, y: O2.y + 1 }]), pivotClear, w, h),
  );
  labels.add('O4', t.O4, 'bold', THEME.text, (w, h) =>
    aroundPoint(O4, awayFrom(O4, [B ?? A, O2, { x: O4.x, y: O4.y + 1 }]), pivotClear, w, h),
  );
  labels.add('A', t.A, 'bold', THEME.text, (w, h) => aroundPoint(A, awayFrom(A, B ? [O2, B] : [O2]), jointClear, w, h));

  const obstacles = groundObstacles(O2, O4, A);
  let drawnAngles: { arcs: SceneArc[]; references: [Px, Px][] } = { arcs: [], references: [] };
  if (pose && B && P) {
    const posed = { O2, A, B, P, O4 };
    addPoseLabels(posed, t, labels, obstacles);
    if (scene.showAngles) drawnAngles = addAngleLabels(scene, pose, posed, labels, obstacles, frameAngle(v));
    addLinkLabels(pose, posed, labels, frameAngle(v));
  }
  labels.add('r1', 'r1', 'regular', THEME.ground, (w, h) =>
    besideSegment(O2, O4, { x: (O2.x + O4.x) / 2, y: (O2.y + O4.y) / 2 - 1 }, STROKES.ground, w, h),
  );

  const design = scene.design ? layoutDesign(scene.design, l, v, joints, bounds) : null;
  if (scene.design && design) {
    for (const d of designLabels(scene.design, design)) labels.add(d.id, d.text, 'regular', d.color, d.candidates);
  }
  if (extras) {
    for (const e of extras.labels) labels.add(e.id, e.text, e.font, e.color, e.candidates);
    obstacles.push(...extras.obstacles);
  }

  labels.requests.sort((x, y) => labelRank(x.id) - labelRank(y.id));
  const { placed, dropped } = placeLabels(labels.requests, bounds, exclusions, obstacles);
  const placedLabels = sceneLabels(placed, labels.meta, warned?.warning ?? null);
  return {
    joints,
    arcs: drawnAngles.arcs,
    references: drawnAngles.references,
    labels: placedLabels.labels,
    warning: placedLabels.warning,
    dropped,
    design,
  };
}
