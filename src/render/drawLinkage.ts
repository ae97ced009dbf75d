import { PI, TWO_PI, angleDiff, radToDeg } from '../solver/angles';
import type { LinkageScene, ScenePose } from './scene';
import { THEME } from './theme';
import type { ViewTransform } from './view';
import { niceStep, toScreenX, toScreenY, toWorld } from './view';

type Ctx = CanvasRenderingContext2D | OffscreenCanvasRenderingContext2D;

interface Px {
  x: number;
  y: number;
}

function px(v: ViewTransform, p: { x: number; y: number }): Px {
  return { x: toScreenX(v, p.x), y: toScreenY(v, p.y) };
}

function drawGrid(ctx: Ctx, scene: LinkageScene, v: ViewTransform): void {
  const step = niceStep(v.scale, 64);
  const tl = toWorld(v, 0, 0);
  const br = toWorld(v, v.width, v.height);
  const i0 = Math.ceil(tl.x / step);
  const i1 = Math.floor(br.x / step);
  const j0 = Math.ceil(br.y / step);
  const j1 = Math.floor(tl.y / step);
  if (i1 - i0 > 400 || j1 - j0 > 400) return;
  ctx.lineWidth = 1;
  for (let i = i0; i <= i1; i++) {
    const x = Math.round(toScreenX(v, i * step)) + 0.5;
    ctx.strokeStyle = i === 0 ? THEME.gridAxis : THEME.grid;
    ctx.beginPath();
    ctx.moveTo(x, 0);
    ctx.lineTo(x, v.height);
    ctx.stroke();
  }
  for (let j = j0; j <= j1; j++) {
    const y = Math.round(toScreenY(v, j * step)) + 0.5;
    ctx.strokeStyle = j === 0 ? THEME.gridAxis : THEME.grid;
    ctx.beginPath();
    ctx.moveTo(0, y);
    ctx.lineTo(v.width, y);
    ctx.stroke();
  }
  ctx.fillStyle = THEME.gridText;
  ctx.font = THEME.font;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'bottom';
  ctx.fillText(scene.text.gridSpacing(scene.text.formatLength(step)), 8, v.height - 6);
}

function drawCurves(ctx: Ctx, scene: LinkageScene, v: ViewTransform): void {
  for (const pass of [false, true]) {
    for (const c of scene.curves) {
      if (c.current !== pass) continue;
      if (!c.current && !scene.showGhost) continue;
      ctx.strokeStyle = c.current ? THEME.trace : THEME.traceGhost;
      ctx.lineWidth = c.current ? 2 : 1.25;
      ctx.setLineDash(c.current ? [] : [4, 4]);
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
        const sx = toScreenX(v, x);
        const sy = toScreenY(v, y);
        if (pen) ctx.lineTo(sx, sy);
        else ctx.moveTo(sx, sy);
        pen = true;
      }
      ctx.stroke();
    }
  }
  ctx.setLineDash([]);
}

function drawGroundPivot(ctx: Ctx, p: Px): void {
  const s = 11;
  ctx.fillStyle = '#eef1f5';
  ctx.strokeStyle = THEME.ground;
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  ctx.moveTo(p.x, p.y);
  ctx.lineTo(p.x - s, p.y + s * 1.5);
  ctx.lineTo(p.x + s, p.y + s * 1.5);
  ctx.closePath();
  ctx.fill();
  ctx.stroke();
  const baseY = p.y + s * 1.5;
  ctx.beginPath();
  ctx.moveTo(p.x - s * 1.7, baseY);
  ctx.lineTo(p.x + s * 1.7, baseY);
  ctx.stroke();
  // Hatching below the base: the conventional sign for the fixed frame.
  ctx.lineWidth = 1;
  ctx.beginPath();
  for (let k = -3; k <= 2; k++) {
    const x0 = p.x + k * 6.5;
    ctx.moveTo(x0 + 6, baseY);
    ctx.lineTo(x0, baseY + 7);
  }
  ctx.stroke();
}

function drawLink(ctx: Ctx, a: Px, b: Px, color: string, width: number): void {
  ctx.strokeStyle = color;
  ctx.lineWidth = width;
  ctx.lineCap = 'round';
  ctx.beginPath();
  ctx.moveTo(a.x, a.y);
  ctx.lineTo(b.x, b.y);
  ctx.stroke();
}

function drawJoint(ctx: Ctx, p: Px, r: number = THEME.jointRadius): void {
  ctx.fillStyle = THEME.joint;
  ctx.strokeStyle = THEME.jointStroke;
  ctx.lineWidth = 1.75;
  ctx.beginPath();
  ctx.arc(p.x, p.y, r, 0, TWO_PI);
  ctx.fill();
  ctx.stroke();
}

function label(ctx: Ctx, text: string, x: number, y: number, color: string = THEME.text, bold = false): void {
  ctx.font = bold ? THEME.fontBold : THEME.font;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.lineWidth = 3;
  ctx.strokeStyle = 'rgba(255,255,255,0.9)';
  ctx.lineJoin = 'round';
  ctx.strokeText(text, x, y);
  ctx.fillStyle = color;
  ctx.fillText(text, x, y);
}

/** Offsets a label away from the linkage: along the bisector of the outward directions, 14 px. */
function away(p: Px, ...others: Px[]): Px {
  let dx = 0;
  let dy = 0;
  for (const o of others) {
    const ox = p.x - o.x;
    const oy = p.y - o.y;
    const d = Math.hypot(ox, oy) || 1;
    dx += ox / d;
    dy += oy / d;
  }
  const d = Math.hypot(dx, dy);
  if (d < 1e-6) return { x: p.x, y: p.y - 16 };
  return { x: p.x + (dx / d) * 16, y: p.y + (dy / d) * 16 };
}

/** Label position beside the middle of segment a-b, 13 px off the line, on the side away from the point `away`. */
function sideOf(a: Px, b: Px, away: Px): Px {
  const mx = (a.x + b.x) / 2;
  const my = (a.y + b.y) / 2;
  const len = Math.hypot(b.x - a.x, b.y - a.y) || 1;
  let nx = -(b.y - a.y) / len;
  let ny = (b.x - a.x) / len;
  if (nx * (away.x - mx) + ny * (away.y - my) > 0) {
    nx = -nx;
    ny = -ny;
  }
  return { x: mx + nx * 13, y: my + ny * 13 };
}

function arcLabel(ctx: Ctx, c: Px, radius: number, fromRad: number, toRad: number, text: string, color: string): void {
  // World angles are CCW with y up; canvas angles are CW with y down, hence the minus signs.
  let sweep = toRad - fromRad;
  if (Math.abs(sweep) < 1e-9) return;
  ctx.strokeStyle = color;
  ctx.lineWidth = 1.25;
  ctx.beginPath();
  ctx.arc(c.x, c.y, radius, -fromRad, -toRad, sweep > 0);
  ctx.stroke();
  sweep = toRad - fromRad;
  const mid = fromRad + sweep / 2;
  const r = radius + 14;
  label(ctx, text, c.x + r * Math.cos(mid), c.y - r * Math.sin(mid), color);
}

function shortest(from: number, to: number): number {
  return angleDiff(to, from);
}

function drawPose(ctx: Ctx, scene: LinkageScene, v: ViewTransform, pose: ScenePose, ghost: boolean): void {
  const A = px(v, pose.A);
  const B = px(v, pose.B);
  const P = px(v, pose.P);
  const O2 = px(v, pose.O2);
  const O4 = px(v, pose.O4);
  if (ghost) {
    ctx.setLineDash([5, 4]);
    drawLink(ctx, O2, A, THEME.ghost, 2);
    drawLink(ctx, A, B, THEME.ghost, 2);
    drawLink(ctx, B, O4, THEME.ghost, 2);
    ctx.setLineDash([]);
    for (const p of [A, B]) {
      ctx.strokeStyle = THEME.ghost;
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.arc(p.x, p.y, 3.5, 0, TWO_PI);
      ctx.stroke();
    }
    return;
  }
  // The coupler is a rigid plate: shade the triangle A-B-P so P reads as part of it.
  ctx.fillStyle = THEME.couplerFill;
  ctx.strokeStyle = 'rgba(15, 157, 118, 0.45)';
  ctx.lineWidth = 1;
  ctx.beginPath();
  ctx.moveTo(A.x, A.y);
  ctx.lineTo(B.x, B.y);
  ctx.lineTo(P.x, P.y);
  ctx.closePath();
  ctx.fill();
  ctx.stroke();
  drawLink(ctx, O2, A, THEME.crank, THEME.linkWidth);
  drawLink(ctx, A, B, THEME.coupler, THEME.linkWidth);
  drawLink(ctx, B, O4, THEME.rocker, THEME.linkWidth);
  drawJoint(ctx, A);
  drawJoint(ctx, B);
  ctx.fillStyle = THEME.trace;
  ctx.strokeStyle = THEME.couplerPoint;
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  ctx.arc(P.x, P.y, 5, 0, TWO_PI);
  ctx.fill();
  ctx.stroke();

  const t = scene.text;
  const la = away(A, O2, B);
  label(ctx, t.A, la.x, la.y, THEME.text, true);
  const lb = away(B, A, O4);
  label(ctx, t.B, lb.x, lb.y, THEME.text, true);
  const lp = away(P, A, B);
  label(ctx, t.P, lp.x, lp.y, THEME.couplerPoint, true);
  const t2 = shortest(0, pose.theta2);
  const t2Pos = t2 >= 0 ? t2 : TWO_PI + t2;
  const arcMid = { x: O2.x + 30 * Math.cos(t2Pos / 2), y: O2.y - 30 * Math.sin(t2Pos / 2) };
  const pOffLine =
    Math.abs((B.x - A.x) * (P.y - A.y) - (B.y - A.y) * (P.x - A.x)) > 4 * Math.hypot(B.x - A.x, B.y - A.y);
  const l2 = sideOf(O2, A, arcMid);
  label(ctx, 'r2', l2.x, l2.y, THEME.crank);
  const l3 = sideOf(A, B, pOffLine ? P : O2);
  label(ctx, 'r3', l3.x, l3.y, THEME.coupler);
  const l4 = sideOf(B, O4, A);
  label(ctx, 'r4', l4.x, l4.y, THEME.rocker);

  if (scene.showAngles) {
    const deg = (r: number) => t.formatAngle(radToDeg(r));
    const r0 = 30;
    arcLabel(ctx, O2, r0, 0, t2Pos, `θ2 ${deg(t2Pos)}`, THEME.crank);
    // Dashed references parallel to the ground line at A and O4.
    ctx.strokeStyle = THEME.gridAxis;
    ctx.setLineDash([3, 3]);
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(A.x, A.y);
    ctx.lineTo(A.x + r0 + 16, A.y);
    ctx.moveTo(O4.x, O4.y);
    ctx.lineTo(O4.x + r0 + 16, O4.y);
    ctx.stroke();
    ctx.setLineDash([]);
    arcLabel(ctx, A, r0 - 4, 0, shortest(0, pose.theta3), `θ3 ${deg(shortest(0, pose.theta3))}`, THEME.coupler);
    arcLabel(ctx, O4, r0 + 4, 0, shortest(0, pose.theta4), `θ4 ${deg(shortest(0, pose.theta4))}`, THEME.rocker);
    const fromB = pose.theta3 + PI;
    const toB = fromB + shortest(fromB, pose.theta4 + PI);
    arcLabel(ctx, B, 22, fromB, toB, `μ ${deg(pose.mu)}`, THEME.angle);
  }
}

function drawWarning(ctx: Ctx, scene: LinkageScene, v: ViewTransform): void {
  const title = scene.text.warning;
  if (!title) return;
  const detail = scene.text.warningDetail;
  ctx.font = THEME.fontBold;
  const w1 = ctx.measureText(title).width;
  ctx.font = THEME.font;
  const w2 = detail ? ctx.measureText(detail).width : 0;
  const w = Math.min(v.width - 16, Math.max(w1, w2) + 28);
  const h = detail ? 50 : 32;
  const x = (v.width - w) / 2;
  const y = 12;
  ctx.fillStyle = THEME.warningFill;
  ctx.strokeStyle = THEME.warning;
  ctx.lineWidth = 1;
  ctx.beginPath();
  ctx.roundRect(x + 0.5, y + 0.5, w, h, 6);
  ctx.fill();
  ctx.stroke();
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.fillStyle = THEME.warning;
  ctx.font = THEME.fontBold;
  ctx.fillText(title, v.width / 2, y + 16);
  if (detail) {
    ctx.font = THEME.font;
    ctx.fillStyle = THEME.text;
    ctx.fillText(detail, v.width / 2, y + 35);
  }
}

/**
 * Draws the linkage scene into ctx in CSS pixels (the caller scales for devicePixelRatio): grid, coupler
 * curves, ground with hatched pivots, the ghost of the other branch, the pose with labels and angle
 * annotations. When there is no pose it draws the ground, the crank at theta2 and the two circles that
 * fail to meet, with a message: never a torn linkage.
 */
export function drawLinkage(ctx: Ctx, scene: LinkageScene, view: ViewTransform): void {
  const v = view;
  ctx.save();
  ctx.fillStyle = THEME.background;
  ctx.fillRect(0, 0, v.width, v.height);
  if (scene.showGrid) drawGrid(ctx, scene, v);
  if (scene.showTrace) drawCurves(ctx, scene, v);

  const l = scene.linkage;
  const O2 = px(v, { x: 0, y: 0 });
  const O4 = px(v, { x: l.r1, y: 0 });
  ctx.strokeStyle = THEME.ground;
  ctx.lineWidth = 1.5;
  ctx.setLineDash([6, 4]);
  ctx.beginPath();
  ctx.moveTo(O2.x, O2.y);
  ctx.lineTo(O4.x, O4.y);
  ctx.stroke();
  ctx.setLineDash([]);
  drawGroundPivot(ctx, O2);
  drawGroundPivot(ctx, O4);
  label(ctx, 'r1', (O2.x + O4.x) / 2, O2.y + 12, THEME.ground);

  if (scene.ghost && scene.showGhost) drawPose(ctx, scene, v, scene.ghost, true);
  if (scene.pose) {
    drawPose(ctx, scene, v, scene.pose, false);
  } else {
    const A = px(v, { x: l.r2 * Math.cos(scene.theta2), y: l.r2 * Math.sin(scene.theta2) });
    ctx.strokeStyle = 'rgba(185, 28, 28, 0.45)';
    ctx.lineWidth = 1.25;
    ctx.setLineDash([4, 4]);
    ctx.beginPath();
    ctx.arc(A.x, A.y, l.r3 * v.scale, 0, TWO_PI);
    ctx.stroke();
    ctx.beginPath();
    ctx.arc(O4.x, O4.y, l.r4 * v.scale, 0, TWO_PI);
    ctx.stroke();
    ctx.setLineDash([]);
    drawLink(ctx, O2, A, THEME.crank, THEME.linkWidth);
    drawJoint(ctx, A);
    const la = away(A, O2);
    label(ctx, scene.text.A, la.x, la.y, THEME.text, true);
  }
  drawJoint(ctx, O2, 6);
  drawJoint(ctx, O4, 6);
  label(ctx, scene.text.O2, O2.x - 20, O2.y - 12, THEME.text, true);
  label(ctx, scene.text.O4, O4.x + 20, O4.y - 12, THEME.text, true);
  drawWarning(ctx, scene, v);
  ctx.restore();
}
