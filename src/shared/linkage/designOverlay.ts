/**
 * The design overlay of the linkage canvas (issue 10): faint outlines of the two dead-centre poses with the
 * rocker's swing arc, and the instant centres I13 and I24 with their construction lines, each off-screen
 * centre shown by an arrow at the canvas edge (a centre at infinity, where its two lines are parallel, by an
 * arrow along them). layoutDesign places it in CSS pixels, designLabels asks the
 * scene's label placement for its texts, drawDesignUnder / drawDesignOver paint it below and above the pose.
 */
import type { DrawContext } from '../canvas/drawContext';
import { PI, TWO_PI, angleDiff } from '../../solver/angles';
import type { Point } from '../../solver/kinematics';
import type { Linkage } from '../../solver/types';
import { STROKES } from '../theme/tokens';
import type { Px, ScreenRect } from '../canvas/rect';
import { halfExtentAlong } from '../canvas/rect';
import { candidatesAround } from '../canvas/labelPlacement';
import type { SceneArc } from './sceneLayout';
import { THEME } from '../canvas/canvasTheme';
import type { ViewTransform } from '../canvas/view';
import { frameAngle, frameToScreen } from '../canvas/view';

type Ctx = DrawContext;

/** Names of the instant centres drawn. */
export type CentreName = 'I13' | 'I24';

/** What the scene carries for the overlay (world units, radians), built by the app from designMetrics. */
export interface SceneDesign {
  /** The usable transmission-angle band, radians: the mu label turns to the warning colour outside it. */
  muBandRad: { lo: number; hi: number };
  /** Dead centres (extended, folded: input and rocker angles, radians) to outline; null hides them. */
  deadCentres: { theta2: number; theta4: number }[] | null;
  /** Canvas label of the swing arc, already formatted ("swing 48.54°"). */
  swingText: string;
  /** Instant centres of the pose (length unit, null at infinity); null hides them. */
  instantCentres: { I13: Point | null; I24: Point | null } | null;
  /** Label of an off-screen centre at the canvas edge, from its name and world point (null: at infinity). */
  offscreenText: (name: CentreName, at: Point | null) => string;
}

/** An off-screen point's marker: where on the inset canvas edge it sits and the direction (screen radians) to the point. */
export interface EdgeMarker {
  at: Px;
  dirRad: number;
}

/**
 * One instant centre on screen: its point (CSS pixels), world point, its construction lines and edge marker. A
 * centre at infinity (world null) has a point far along its parallel lines, so it always has an edge marker.
 */
export interface CentreLayout {
  name: CentreName;
  world: Point | null;
  p: Px;
  /** Null when the point is on the canvas (inside the edge inset). */
  edge: EdgeMarker | null;
  /** Construction lines, clipped to the canvas (CSS pixels). */
  lines: [Px, Px][];
}

/** The overlay in CSS pixels. */
export interface DesignLayout {
  deadCentres: { O2: Px; A: Px; B: Px; O4: Px }[];
  swingArc: SceneArc | null;
  centres: CentreLayout[];
}

/** A label the overlay asks the scene's label placement for (its ids are LabelIds of sceneLayout). */
export interface DesignLabel {
  id: 'swing' | CentreName;
  text: string;
  color: string;
  candidates: (width: number, height: number) => Px[];
}

/** A point of the linkage's frame to CSS pixels (through the view's frame when the linkage is placed). */
function px(v: ViewTransform, p: Point): Px {
  return frameToScreen(v, p);
}

/**
 * Where the edge marker of p goes: null when p lies inside rect shrunk by inset; otherwise the point where
 * the ray from the rect's centre towards p leaves the shrunk rect, and the ray's direction (screen radians,
 * atan2 with y down). Non-finite p gives null.
 */
export function edgeMarker(p: Px, rect: ScreenRect, inset: number): EdgeMarker | null {
  if (!Number.isFinite(p.x) || !Number.isFinite(p.y)) return null;
  const x0 = rect.x + inset;
  const y0 = rect.y + inset;
  const x1 = rect.x + rect.width - inset;
  const y1 = rect.y + rect.height - inset;
  if (p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1) return null;
  const cx = (x0 + x1) / 2;
  const cy = (y0 + y1) / 2;
  const dx = p.x - cx;
  const dy = p.y - cy;
  // The largest step along (dx, dy) that stays inside: the nearer of the vertical and horizontal edges.
  const tx = dx !== 0 ? (dx > 0 ? x1 - cx : x0 - cx) / dx : Infinity;
  const ty = dy !== 0 ? (dy > 0 ? y1 - cy : y0 - cy) / dy : Infinity;
  const t = Math.min(tx, ty);
  return { at: { x: cx + dx * t, y: cy + dy * t }, dirRad: Math.atan2(dy, dx) };
}

/**
 * The segment of the line through a and b that lies inside rect (Liang-Barsky on the infinite line), or null
 * when the line misses it. Used to draw construction lines towards far-away instant centres without huge
 * coordinates; only the part between the points the caller asks for is kept (tMin..tMax along a->b).
 */
export function clipLine(a: Px, b: Px, rect: ScreenRect, tMin: number, tMax: number): [Px, Px] | null {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  let t0 = tMin;
  let t1 = tMax;
  const ps = [-dx, dx, -dy, dy];
  const qs = [a.x - rect.x, rect.x + rect.width - a.x, a.y - rect.y, rect.y + rect.height - a.y];
  for (let k = 0; k < 4; k++) {
    if (ps[k] === 0) {
      if (qs[k] < 0) return null;
      continue;
    }
    const t = qs[k] / ps[k];
    if (ps[k] < 0) t0 = Math.max(t0, t);
    else t1 = Math.min(t1, t);
  }
  if (!(t0 < t1)) return null;
  return [
    { x: a.x + dx * t0, y: a.y + dy * t0 },
    { x: a.x + dx * t1, y: a.y + dy * t1 },
  ];
}

/** The line through a and b from the first to the last of a, b, c along it (c on the line), clipped to rect. */
function spanClipped(a: Px, b: Px, c: Px, rect: ScreenRect): [Px, Px] | null {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  const len2 = dx * dx + dy * dy;
  if (!(len2 > 0)) return null;
  const tc = ((c.x - a.x) * dx + (c.y - a.y) * dy) / len2;
  return clipLine(a, b, rect, Math.min(0, 1, tc), Math.max(0, 1, tc));
}

/**
 * Screen layout of the overlay for the pose's joints (CSS pixels) at this view; rect is the canvas. The
 * swing arc runs at O4 with radius r4 between the two dead-centre rocker angles, the short way round.
 */
export function layoutDesign(
  design: SceneDesign,
  l: Linkage,
  v: ViewTransform,
  joints: { O2: Px; O4: Px; A: Px; B: Px | null },
  rect: ScreenRect,
): DesignLayout {
  const deadCentres: DesignLayout['deadCentres'] = [];
  let swingArc: SceneArc | null = null;
  if (design.deadCentres && design.deadCentres.length === 2) {
    for (const dc of design.deadCentres) {
      deadCentres.push({
        O2: joints.O2,
        O4: joints.O4,
        A: px(v, { x: l.r2 * Math.cos(dc.theta2), y: l.r2 * Math.sin(dc.theta2) }),
        B: px(v, { x: l.r1 + l.r4 * Math.cos(dc.theta4), y: l.r4 * Math.sin(dc.theta4) }),
      });
    }
    const [a, b] = design.deadCentres;
    const g = frameAngle(v);
    swingArc = {
      centre: joints.O4,
      radiusPx: l.r4 * v.scale,
      fromRad: g + a.theta4,
      toRad: g + a.theta4 + angleDiff(b.theta4, a.theta4),
      color: THEME.deadCentre,
    };
  }
  const centres: CentreLayout[] = [];
  const ic = design.instantCentres;
  // Lines are clipped to the canvas grown by a margin, so their ends (and round caps) stay off-screen.
  const clipRect = { x: rect.x - 50, y: rect.y - 50, width: rect.width + 100, height: rect.height + 100 };
  if (ic && joints.B) {
    const B = joints.B;
    const add = (name: CentreName, world: Point | null, pairs: [Px, Px][]) => {
      const lines: [Px, Px][] = [];
      if (!world) {
        // At infinity: the two lines are parallel. Draw them across the canvas; the marker points along them.
        const [a, b] = pairs[0];
        const len = Math.hypot(b.x - a.x, b.y - a.y);
        if (!(len > 0)) return;
        const reach = (2 * (clipRect.width + clipRect.height)) / len;
        for (const [c, d] of pairs) {
          const s = clipLine(c, d, clipRect, -reach, reach);
          if (s) lines.push(s);
        }
        const far = 1e7 / len;
        const mid = { x: rect.x + rect.width / 2, y: rect.y + rect.height / 2 };
        const p = { x: mid.x + (b.x - a.x) * far, y: mid.y + (b.y - a.y) * far };
        centres.push({ name, world: null, p, edge: edgeMarker(p, rect, STROKES.edgeInset), lines });
        return;
      }
      const p = px(v, world);
      for (const [a, b] of pairs) {
        const s = spanClipped(a, b, p, clipRect);
        if (s) lines.push(s);
      }
      centres.push({ name, world, p, edge: edgeMarker(p, rect, STROKES.edgeInset), lines });
    };
    add('I13', ic.I13, [
      [joints.O2, joints.A],
      [joints.O4, B],
    ]);
    add('I24', ic.I24, [
      [joints.A, B],
      [joints.O2, joints.O4],
    ]);
  }
  return { deadCentres, swingArc, centres };
}

/** Eight directions 45° apart: down-right on screen (y down) first, then turning counter-clockwise as seen. */
const RING_ROTATIONS = [0, 1, 2, 3, 4, 5, 6, 7].map((k) => (-k * TWO_PI) / 8);
const RING_START = { x: Math.cos(-PI / 4), y: -Math.sin(-PI / 4) };

/** Label centres around a point: eight directions at growing gaps beyond a clearance. */
function ring(p: Px, clearance: number, width: number, height: number): Px[] {
  return candidatesAround(p, RING_START, RING_ROTATIONS, [3, 9, 18], clearance, width, height);
}

/** The overlay's labels: the swing beside its arc, each centre beside its point or its edge marker. */
export function designLabels(design: SceneDesign, layout: DesignLayout): DesignLabel[] {
  const out: DesignLabel[] = [];
  const arc = layout.swingArc;
  if (arc) {
    const mid = (arc.fromRad + arc.toRad) / 2;
    out.push({
      id: 'swing',
      text: design.swingText,
      color: THEME.deadCentre,
      candidates: (w, h) => {
        const pts: Px[] = [];
        for (const gap of [4, 12, 24]) {
          for (const f of [0, 0.25, -0.25, 0.5, -0.5]) {
            const phi = mid + f * (arc.toRad - arc.fromRad);
            const ux = Math.cos(phi);
            const uy = -Math.sin(phi);
            const d = arc.radiusPx + gap + halfExtentAlong(ux, uy, w, h);
            pts.push({ x: arc.centre.x + ux * d, y: arc.centre.y + uy * d });
          }
        }
        return pts;
      },
    });
  }
  for (const c of layout.centres) {
    const text = c.edge ? design.offscreenText(c.name, c.world) : c.name;
    out.push({
      id: c.name,
      text,
      color: THEME.instantCentre,
      candidates: (w, h) => {
        if (!c.edge) return ring(c.p, STROKES.instantCentreRadius + 2, w, h);
        // Beside the arrow, pulled inwards (opposite the direction to the point) so the box stays on the canvas,
        // then slid to either side of the arrow when the linkage is in the way.
        const ux = -Math.cos(c.edge.dirRad);
        const uy = -Math.sin(c.edge.dirRad);
        const pts: Px[] = [];
        for (const gap of [4, 10, 20]) {
          const d = gap + halfExtentAlong(ux, uy, w, h);
          const base = { x: c.edge.at.x + ux * d, y: c.edge.at.y + uy * d };
          pts.push(base, ...ring(c.edge.at, STROKES.edgeArrow, w, h));
          for (const slide of [16, -16, 32, -32, 56, -56]) pts.push({ x: base.x - uy * slide, y: base.y + ux * slide });
        }
        return pts;
      },
    });
  }
  return out;
}

function polyline(ctx: Ctx, pts: Px[]): void {
  ctx.beginPath();
  ctx.moveTo(pts[0].x, pts[0].y);
  for (let i = 1; i < pts.length; i++) ctx.lineTo(pts[i].x, pts[i].y);
  ctx.stroke();
}

/** Paints what goes under the pose: dead-centre outlines, the swing arc and the construction lines. */
export function drawDesignUnder(ctx: Ctx, layout: DesignLayout): void {
  ctx.save();
  ctx.lineCap = 'round';
  ctx.strokeStyle = THEME.deadCentre;
  ctx.lineWidth = STROKES.deadCentre;
  ctx.setLineDash(STROKES.deadCentreDash);
  for (const dc of layout.deadCentres) polyline(ctx, [dc.O2, dc.A, dc.B, dc.O4]);
  const arc = layout.swingArc;
  if (arc) {
    ctx.setLineDash([]);
    ctx.beginPath();
    ctx.arc(arc.centre.x, arc.centre.y, arc.radiusPx, -arc.fromRad, -arc.toRad, arc.toRad > arc.fromRad);
    ctx.stroke();
  }
  ctx.strokeStyle = THEME.instantCentre;
  ctx.lineWidth = STROKES.construction;
  ctx.setLineDash(STROKES.constructionDash);
  for (const c of layout.centres) for (const [a, b] of c.lines) polyline(ctx, [a, b]);
  ctx.restore();
}

/** Paints what goes over the pose: each on-screen instant centre as a ring, each off-screen one as an edge arrow. */
export function drawDesignOver(ctx: Ctx, layout: DesignLayout): void {
  ctx.save();
  ctx.strokeStyle = THEME.instantCentre;
  ctx.fillStyle = THEME.instantCentre;
  ctx.lineWidth = 1.5;
  for (const c of layout.centres) {
    if (!c.edge) {
      ctx.beginPath();
      ctx.arc(c.p.x, c.p.y, STROKES.instantCentreRadius, 0, TWO_PI);
      ctx.stroke();
      ctx.beginPath();
      ctx.arc(c.p.x, c.p.y, 1.5, 0, TWO_PI);
      ctx.fill();
      continue;
    }
    // An arrowhead at the edge pointing at the centre.
    const { at, dirRad } = c.edge;
    const L = STROKES.edgeArrow;
    const tip = { x: at.x + (Math.cos(dirRad) * L) / 2, y: at.y + (Math.sin(dirRad) * L) / 2 };
    const back = (s: number) => ({
      x: tip.x - Math.cos(dirRad + s) * L,
      y: tip.y - Math.sin(dirRad + s) * L,
    });
    ctx.beginPath();
    ctx.moveTo(tip.x, tip.y);
    const l = back(0.45);
    const r = back(-0.45);
    ctx.lineTo(l.x, l.y);
    ctx.lineTo(r.x, r.y);
    ctx.closePath();
    ctx.fill();
  }
  ctx.restore();
}

/** Whether mu (radians) lies outside the usable band of the design (false without a design). */
export function muOutsideBand(design: SceneDesign | undefined, muRad: number): boolean {
  if (!design) return false;
  return muRad < design.muBandRad.lo || muRad > design.muBandRad.hi;
}
