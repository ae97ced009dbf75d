import { drawGrid } from '../canvas/drawGrid';
import { drawGroundTriangle, drawJoint, drawLink } from './linkPrimitives';
import { TWO_PI } from '../../solver/angles';
import { STROKES } from '../theme/tokens';
import { drawDesignOver, drawDesignUnder } from './designOverlay';
import { SIMULATOR_POSE, drawFourBarPose } from './drawFourBarPose';
import type { DrawContext } from '../canvas/drawContext';
import { drawPanelBox } from '../canvas/drawContext';
import { drawVectorArrows, drawVectorLegend, vectorOverlay } from './motionVectors';
import { drawForceArrows, forceOverlay } from './forceVectors';
import type { Px, ScreenRect } from '../canvas/rect';
import type { LinkageScene, ScenePose } from './scene';
import type { LabelFont, MeasureText, SceneArc, SceneLabel, SceneLayout, WarningBox } from './sceneLayout';
import { GRID_TARGET_PX, WARNING_BOX, layoutScene } from './sceneLayout';
import { THEME } from '../canvas/canvasTheme';
import type { ViewTransform } from '../canvas/view';
import { frameToScreen, toScreenX, toScreenY } from '../canvas/view';

// Any DrawContext: a canvas's 2D context, or SvgContext for the vector export.
type Ctx = DrawContext;

function fontOf(font: LabelFont): string {
  return font === 'bold' ? THEME.fontBold : THEME.font;
}

/** Widths each context already measured, by font and text (the labels' fonts are system fonts: a width never changes). */
const measuredBy = new WeakMap<Ctx, Map<string, number>>();
/** Entries kept before the cache starts over (angle labels bring new texts every frame). */
const MEASURED_MAX = 4096;

/**
 * Text widths (CSS pixels) measured by the canvas itself, in the label fonts. Widths are cached by font and
 * text, and the context's font is set only when it changes: setting it parses the font string every time.
 */
export function canvasMeasure(ctx: Ctx): MeasureText {
  let current = '';
  let measured = measuredBy.get(ctx);
  if (!measured) {
    measured = new Map();
    measuredBy.set(ctx, measured);
  }
  const cache = measured;
  return (text, font) => {
    const css = fontOf(font);
    const key = `${css}\n${text}`;
    const known = cache.get(key);
    if (known !== undefined) return known;
    if (css !== current) {
      ctx.font = css;
      current = css;
    }
    const width = ctx.measureText(text).width;
    if (cache.size >= MEASURED_MAX) cache.clear();
    cache.set(key, width);
    return width;
  };
}

/** A point of the linkage's frame to CSS pixels (through the view's frame when the linkage is placed). */
function px(v: ViewTransform, p: { x: number; y: number }): Px {
  return frameToScreen(v, p);
}

function drawCurves(ctx: Ctx, scene: LinkageScene, v: ViewTransform): void {
  for (const pass of [false, true]) {
    for (const c of scene.curves) {
      if (c.current !== pass) continue;
      if (!c.current && !scene.showGhost) continue;
      ctx.strokeStyle = c.current ? THEME.trace : THEME.traceGhost;
      ctx.lineWidth = c.current ? STROKES.trace : STROKES.traceGhost;
      ctx.setLineDash(c.current ? [] : STROKES.traceGhostDash);
      ctx.beginPath();
      let pen = false;
      const n = Math.min(c.x.length, c.y.length);
      for (let i = 0; i < n; i++) {
        const x = c.x[i];
        const y = c.y[i];
        if (!Number.isFinite(x) || !Number.isFinite(y)) {
          pen = false;
          continue;
        }
        const s = px(v, { x, y });
        if (pen) ctx.lineTo(s.x, s.y);
        else ctx.moveTo(s.x, s.y);
        pen = true;
      }
      ctx.stroke();
    }
  }
  ctx.setLineDash([]);
}

/** The sign of a fixed pivot at p (CSS pixels): triangle, base and hatching. */
export function drawGroundPivot(ctx: Ctx, p: Px): void {
  // Triangle, base and hatching: the conventional sign for the fixed frame (groundSymbolRect bounds it).
  const s = 11;
  drawGroundTriangle(ctx, p, s);
  const baseY = p.y + s * 1.5;
  ctx.beginPath();
  ctx.moveTo(p.x - s * 1.7, baseY);
  ctx.lineTo(p.x + s * 1.7, baseY);
  ctx.stroke();
  ctx.lineWidth = STROKES.groundHatch;
  ctx.beginPath();
  for (let k = -3; k <= 2; k++) {
    const x0 = p.x + k * 6.5;
    ctx.moveTo(x0 + 6, baseY);
    ctx.lineTo(x0, baseY + 7);
  }
  ctx.stroke();
}

function drawArc(ctx: Ctx, a: SceneArc): void {
  // World angles are CCW with y up; canvas angles are CW with y down, hence the minus signs.
  ctx.strokeStyle = a.color;
  ctx.lineWidth = STROKES.arc;
  ctx.beginPath();
  ctx.arc(a.centre.x, a.centre.y, a.radiusPx, -a.fromRad, -a.toRad, a.toRad > a.fromRad);
  ctx.stroke();
}

function drawLabel(ctx: Ctx, l: SceneLabel): void {
  ctx.font = fontOf(l.font);
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.lineWidth = STROKES.labelHalo;
  ctx.strokeStyle = THEME.labelHalo;
  ctx.lineJoin = 'round';
  ctx.strokeText(l.text, l.centre.x, l.centre.y);
  ctx.fillStyle = l.color;
  ctx.fillText(l.text, l.centre.x, l.centre.y);
}

function drawGhost(ctx: Ctx, v: ViewTransform, pose: ScenePose): void {
  const A = px(v, pose.A);
  const B = px(v, pose.B);
  ctx.setLineDash(STROKES.ghostDash);
  drawLink(ctx, px(v, pose.O2), A, THEME.ghost, STROKES.ghost);
  drawLink(ctx, A, B, THEME.ghost, STROKES.ghost);
  drawLink(ctx, B, px(v, pose.O4), THEME.ghost, STROKES.ghost);
  ctx.setLineDash([]);
  for (const p of [A, B]) {
    ctx.strokeStyle = THEME.ghost;
    ctx.lineWidth = STROKES.ground;
    ctx.beginPath();
    ctx.arc(p.x, p.y, STROKES.ghostJointRadius, 0, TWO_PI);
    ctx.stroke();
  }
}

function drawPose(ctx: Ctx, layout: SceneLayout): void {
  const { O2, O4, A, B, P } = layout.joints;
  if (!B || !P) return;
  drawFourBarPose(ctx, { O2, A, B, O4, P }, SIMULATOR_POSE);
  ctx.strokeStyle = THEME.reference;
  ctx.setLineDash(STROKES.referenceDash);
  ctx.lineWidth = STROKES.reference;
  ctx.beginPath();
  for (const [p, q] of layout.references) {
    ctx.moveTo(p.x, p.y);
    ctx.lineTo(q.x, q.y);
  }
  ctx.stroke();
  ctx.setLineDash([]);
  for (const a of layout.arcs) drawArc(ctx, a);
}

function drawUnassembled(ctx: Ctx, scene: LinkageScene, v: ViewTransform, layout: SceneLayout): void {
  // The two circles that fail to meet: B's reach from A and from O4.
  const { O2, O4, A } = layout.joints;
  ctx.strokeStyle = THEME.warning;
  ctx.lineWidth = STROKES.traceGhost;
  ctx.setLineDash(STROKES.traceGhostDash);
  ctx.beginPath();
  ctx.arc(A.x, A.y, scene.linkage.r3 * v.scale, 0, TWO_PI);
  ctx.stroke();
  ctx.beginPath();
  ctx.arc(O4.x, O4.y, scene.linkage.r4 * v.scale, 0, TWO_PI);
  ctx.stroke();
  ctx.setLineDash([]);
  drawLink(ctx, O2, A, THEME.crank, STROKES.link);
  drawJoint(ctx, A, STROKES.jointRadius);
}

function drawWarning(ctx: Ctx, w: WarningBox): void {
  const { box } = w;
  drawPanelBox(ctx, box, THEME.warningFill, THEME.warning, 6);
  const cx = box.x + box.width / 2;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.fillStyle = THEME.warning;
  ctx.font = THEME.fontBold;
  ctx.fillText(w.title, cx, box.y + WARNING_BOX.titleY);
  if (w.detail) {
    ctx.font = THEME.font;
    ctx.fillStyle = THEME.text;
    ctx.fillText(w.detail, cx, box.y + WARNING_BOX.detailY);
  }
}

/**
 * The part of the scene that stays put while the linkage moves: the background, grid, coupler curves and
 * the ground with its hatched pivots, in CSS pixels. drawLinkage draws it first; the live canvas keeps it in
 * a bitmap and redraws it only when sameBackground says it changed.
 */
export function drawLinkageBackground(ctx: Ctx, scene: LinkageScene, view: ViewTransform): void {
  const v = view;
  ctx.save();
  ctx.fillStyle = THEME.background;
  ctx.fillRect(0, 0, v.width, v.height);
  if (scene.showGrid) drawGrid(ctx, v, GRID_TARGET_PX);
  if (scene.showTrace) drawCurves(ctx, scene, v);
  const O2 = px(v, { x: 0, y: 0 });
  const O4 = px(v, { x: scene.linkage.r1, y: 0 });
  ctx.strokeStyle = THEME.ground;
  ctx.lineWidth = STROKES.ground;
  ctx.setLineDash(STROKES.groundDash);
  ctx.beginPath();
  ctx.moveTo(O2.x, O2.y);
  ctx.lineTo(O4.x, O4.y);
  ctx.stroke();
  ctx.setLineDash([]);
  drawGroundPivot(ctx, O2);
  drawGroundPivot(ctx, O4);
  if (scene.markers) drawMarkers(ctx, scene.markers, v);
  ctx.restore();
}

/** Radius of a marker's ring (CSS pixels). */
const MARKER_RADIUS_PX = 6;

/** The task's markers (synthesis targets, world coordinates): a ring with a cross at each. */
function drawMarkers(ctx: Ctx, markers: readonly { x: number; y: number }[], v: ViewTransform): void {
  ctx.strokeStyle = THEME.target;
  ctx.lineWidth = 1.75;
  for (const m of markers) {
    const x = toScreenX(v, m.x);
    const y = toScreenY(v, m.y);
    if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
    ctx.beginPath();
    ctx.arc(x, y, MARKER_RADIUS_PX, 0, TWO_PI);
    ctx.moveTo(x - 3, y);
    ctx.lineTo(x + 3, y);
    ctx.moveTo(x, y - 3);
    ctx.lineTo(x, y + 3);
    ctx.stroke();
  }
}

/** Whether two scenes draw the same background (drawLinkageBackground) in the same view transform. */
export function sameBackground(a: LinkageScene, b: LinkageScene): boolean {
  if (a.showGrid !== b.showGrid || a.showTrace !== b.showTrace || a.showGhost !== b.showGhost) return false;
  if (a.linkage.r1 !== b.linkage.r1) return false;
  if (a.placement !== b.placement || a.markers !== b.markers) return false;
  if (!a.showTrace) return true;
  if (a.curves.length !== b.curves.length) return false;
  return a.curves.every((c, i) => c.x === b.curves[i].x && c.y === b.curves[i].y && c.current === b.curves[i].current);
}

/**
 * Draws what moves over the background (drawLinkageBackground must be under it): the ghost of the other
 * branch, the pose with its angle arcs, the pivots, the design overlay, the motion vectors and pin forces, then
 * the labels where layoutScene placed them (never overlapping each other or the exclusion rectangles, e.g. the zoom
 * buttons from canvasToolsRect). With no pose it draws the crank at theta2 and the two circles that fail to
 * meet, with a message: never a torn linkage. Returns the layout it drew.
 */
export function drawLinkageForeground(
  ctx: Ctx,
  scene: LinkageScene,
  view: ViewTransform,
  exclusions: readonly ScreenRect[] = [],
): SceneLayout {
  const v = view;
  ctx.save();
  const measure = canvasMeasure(ctx);
  // The motion vectors' and pin forces' labels and shafts join the layout; their legends' corner is kept clear.
  const vectors = scene.vectors ? vectorOverlay(scene.vectors, scene.pose, v, measure) : null;
  const forces = scene.forces ? forceOverlay(scene.forces, scene.pose, v, measure, vectors?.legend?.box ?? null) : null;
  const excluded = [...exclusions, ...(vectors?.exclusions ?? []), ...(forces?.exclusions ?? [])];
  const extras =
    vectors && forces
      ? {
          labels: [...vectors.extras.labels, ...forces.extras.labels],
          obstacles: [...vectors.extras.obstacles, ...forces.extras.obstacles],
        }
      : (vectors?.extras ?? forces?.extras ?? null);
  const layout = layoutScene(scene, v, measure, excluded, extras);
  const { O2, O4 } = layout.joints;
  if (scene.ghost && scene.showGhost) drawGhost(ctx, v, scene.ghost);
  if (layout.design) drawDesignUnder(ctx, layout.design);
  if (scene.pose) drawPose(ctx, layout);
  else drawUnassembled(ctx, scene, v, layout);
  drawJoint(ctx, O2, STROKES.pivotRadius);
  drawJoint(ctx, O4, STROKES.pivotRadius);
  if (layout.design) drawDesignOver(ctx, layout.design);
  if (vectors) drawVectorArrows(ctx, vectors);
  if (forces) drawForceArrows(ctx, forces);
  for (const l of layout.labels) drawLabel(ctx, l);
  if (vectors) drawVectorLegend(ctx, vectors);
  if (forces) drawVectorLegend(ctx, forces);
  if (layout.warning) drawWarning(ctx, layout.warning);
  ctx.restore();
  return layout;
}

/**
 * Draws the linkage scene into ctx in CSS pixels (the caller scales for devicePixelRatio): the background
 * (grid, coupler curves, ground with hatched pivots), then the foreground (ghost, pose, arcs, design overlay,
 * motion vectors, pin forces and their legends, labels, warning). Returns the layout it drew.
 */
export function drawLinkage(
  ctx: Ctx,
  scene: LinkageScene,
  view: ViewTransform,
  exclusions: readonly ScreenRect[] = [],
): SceneLayout {
  drawLinkageBackground(ctx, scene, view);
  return drawLinkageForeground(ctx, scene, view, exclusions);
}
