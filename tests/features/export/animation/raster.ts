import { jointPositions, solveClosedForm } from '../../../../src/solver';
import type { Branch, Linkage } from '../../../../src/solver';

/** An RGB colour, 0..255 each. */
export type Rgb = readonly [r: number, g: number, b: number];

/** An RGBA image in memory (row-major, 4 bytes a pixel), like ImageData. */
export interface Raster {
  width: number;
  height: number;
  data: Uint8ClampedArray;
}

/** A width x height raster filled with one opaque colour. */
export function createRaster(width: number, height: number, fill: Rgb): Raster {
  const data = new Uint8ClampedArray(width * height * 4);
  for (let i = 0; i < data.length; i += 4) {
    data[i] = fill[0];
    data[i + 1] = fill[1];
    data[i + 2] = fill[2];
    data[i + 3] = 255;
  }
  return { width, height, data };
}

function blend(r: Raster, x: number, y: number, c: Rgb, coverage: number): void {
  if (coverage <= 0 || x < 0 || y < 0 || x >= r.width || y >= r.height) return;
  const a = Math.min(1, coverage);
  const i = (y * r.width + x) * 4;
  r.data[i] = Math.round(r.data[i] * (1 - a) + c[0] * a);
  r.data[i + 1] = Math.round(r.data[i + 1] * (1 - a) + c[1] * a);
  r.data[i + 2] = Math.round(r.data[i + 2] * (1 - a) + c[2] * a);
}

/** Fills the pixels of an axis-aligned rectangle (integer pixel edges, no anti-aliasing). */
export function fillRect(r: Raster, x: number, y: number, w: number, h: number, c: Rgb): void {
  for (let j = Math.max(0, y); j < Math.min(r.height, y + h); j++) {
    for (let i = Math.max(0, x); i < Math.min(r.width, x + w); i++) blend(r, i, j, c, 1);
  }
}

/** Strokes a segment widthPx wide with anti-aliased edges (coverage from the pixel centre's distance). */
export function strokeSegment(
  r: Raster,
  x0: number,
  y0: number,
  x1: number,
  y1: number,
  widthPx: number,
  c: Rgb,
): void {
  const h = widthPx / 2;
  const dx = x1 - x0;
  const dy = y1 - y0;
  const len2 = dx * dx + dy * dy || 1;
  for (let j = Math.floor(Math.min(y0, y1) - h - 1); j <= Math.ceil(Math.max(y0, y1) + h + 1); j++) {
    for (let i = Math.floor(Math.min(x0, x1) - h - 1); i <= Math.ceil(Math.max(x0, x1) + h + 1); i++) {
      const px = i + 0.5;
      const py = j + 0.5;
      const t = Math.max(0, Math.min(1, ((px - x0) * dx + (py - y0) * dy) / len2));
      const d = Math.hypot(px - (x0 + t * dx), py - (y0 + t * dy));
      blend(r, i, j, c, h + 0.5 - d);
    }
  }
}

/** Fills a disc with an anti-aliased edge. */
export function fillDisc(r: Raster, cx: number, cy: number, radius: number, c: Rgb): void {
  for (let j = Math.floor(cy - radius - 1); j <= Math.ceil(cy + radius + 1); j++) {
    for (let i = Math.floor(cx - radius - 1); i <= Math.ceil(cx + radius + 1); i++) {
      blend(r, i, j, c, radius + 0.5 - Math.hypot(i + 0.5 - cx, j + 0.5 - cy));
    }
  }
}

const BACKGROUND: Rgb = [255, 255, 255];
const GRID: Rgb = [232, 236, 241];
const AXIS: Rgb = [200, 207, 216];
const TRACE: Rgb = [217, 119, 6];
const GROUND: Rgb = [100, 116, 139];
const CRANK: Rgb = [37, 99, 235];
const COUPLER: Rgb = [22, 163, 74];
const ROCKER: Rgb = [220, 38, 38];
const JOINT: Rgb = [30, 41, 59];

/**
 * A linkage-like frame for the GIF tests and benchmark: white background, a grid, the coupler-point trace
 * (a static curve), and the links and joints of the pose at theta2Rad, anti-aliased like a canvas drawing.
 * The linkage is scaled to fit width x height with a margin.
 */
export function drawLinkageFrame(
  width: number,
  height: number,
  l: Linkage,
  theta2Rad: number,
  branch: Branch,
  trace: readonly { x: number; y: number }[],
): Raster {
  const r = createRaster(width, height, BACKGROUND);
  const reach = l.r2 + Math.max(l.r3, l.r4);
  const minX = -reach;
  const maxX = l.r1 + reach;
  const scale = Math.min((width * 0.84) / (maxX - minX), (height * 0.84) / (2 * reach));
  const sx = (x: number) => width / 2 + (x - (minX + maxX) / 2) * scale;
  const sy = (y: number) => height / 2 - y * scale;
  for (let x = 0; x < width; x += 40) fillRect(r, x, 0, 1, height, GRID);
  for (let y = 0; y < height; y += 40) fillRect(r, 0, y, width, 1, GRID);
  fillRect(r, Math.round(sx(0)), 0, 1, height, AXIS);
  fillRect(r, 0, Math.round(sy(0)), width, 1, AXIS);
  for (let k = 0; k + 1 < trace.length; k++) {
    strokeSegment(r, sx(trace[k].x), sy(trace[k].y), sx(trace[k + 1].x), sy(trace[k + 1].y), 2, TRACE);
  }
  strokeSegment(r, sx(0), sy(0), sx(l.r1), sy(0), 3, GROUND);
  const a = solveClosedForm(l, theta2Rad, branch);
  if (a) {
    const j = jointPositions(l, theta2Rad, a);
    const P = { x: (j.A.x + j.B.x) / 2 + (j.B.y - j.A.y) * 0.4, y: (j.A.y + j.B.y) / 2 - (j.B.x - j.A.x) * 0.4 };
    strokeSegment(r, sx(j.A.x), sy(j.A.y), sx(P.x), sy(P.y), 3, COUPLER);
    strokeSegment(r, sx(j.B.x), sy(j.B.y), sx(P.x), sy(P.y), 3, COUPLER);
    strokeSegment(r, sx(j.O2.x), sy(j.O2.y), sx(j.A.x), sy(j.A.y), 5, CRANK);
    strokeSegment(r, sx(j.A.x), sy(j.A.y), sx(j.B.x), sy(j.B.y), 5, COUPLER);
    strokeSegment(r, sx(j.O4.x), sy(j.O4.y), sx(j.B.x), sy(j.B.y), 5, ROCKER);
    for (const p of [j.O2, j.O4, j.A, j.B]) fillDisc(r, sx(p.x), sy(p.y), 5, JOINT);
    fillDisc(r, sx(P.x), sy(P.y), 4, TRACE);
  }
  return r;
}

/** Points of the coupler-point trace drawn by drawLinkageFrame, over samples input angles of one branch. */
export function couplerTrace(l: Linkage, branch: Branch, samples: number): { x: number; y: number }[] {
  const out: { x: number; y: number }[] = [];
  for (let k = 0; k <= samples; k++) {
    const t = (2 * Math.PI * k) / samples;
    const a = solveClosedForm(l, t, branch);
    if (!a) continue;
    const j = jointPositions(l, t, a);
    out.push({ x: (j.A.x + j.B.x) / 2 + (j.B.y - j.A.y) * 0.4, y: (j.A.y + j.B.y) / 2 - (j.B.x - j.A.x) * 0.4 });
  }
  return out;
}
