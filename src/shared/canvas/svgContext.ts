import { PI, TWO_PI, radToDeg } from '../../solver/angles';
import type { DrawContext } from './drawContext';

/** Text width in CSS pixels of text in a CSS font shorthand (e.g. '600 12px system-ui'). */
export type MeasureFont = (text: string, font: string) => number;

/** Options of SvgContext. */
export interface SvgContextOptions {
  /** How measureText measures; default a canvas's own measureText, or 0.6 em a character where there is no canvas. */
  measure?: MeasureFont;
}

/** An affine matrix [a, b, c, d, e, f]: x' = a x + c y + e, y' = b x + d y + f (the canvas's and SVG's order). */
type Matrix = [number, number, number, number, number, number];

interface DrawState {
  matrix: Matrix;
  fillStyle: string;
  strokeStyle: string;
  lineWidth: number;
  lineCap: CanvasLineCap;
  lineJoin: CanvasLineJoin;
  font: string;
  textAlign: CanvasTextAlign;
  textBaseline: CanvasTextBaseline;
  globalAlpha: number;
  dash: number[];
}

const IDENTITY: Matrix = [1, 0, 0, 1, 0, 0];

function multiply(m: Matrix, n: Matrix): Matrix {
  return [
    m[0] * n[0] + m[2] * n[1],
    m[1] * n[0] + m[3] * n[1],
    m[0] * n[2] + m[2] * n[3],
    m[1] * n[2] + m[3] * n[3],
    m[0] * n[4] + m[2] * n[5] + m[4],
    m[1] * n[4] + m[3] * n[5] + m[5],
  ];
}

/** Escapes text for an XML text node or a double-quoted attribute. */
export function escapeXml(s: string): string {
  return s
    .replace(/&/g, '&amp;')
    .replace(/</g, '&lt;')
    .replace(/>/g, '&gt;')
    .replace(/"/g, '&quot;')
    .replace(/'/g, '&apos;');
}

/** A number for SVG: at most 3 decimals (a thousandth of a CSS pixel), no '-0'. */
function num(v: number): string {
  const r = Math.round(v * 1000) / 1000;
  return String(r === 0 ? 0 : r);
}

/** The parts of a CSS font shorthand SVG takes as attributes. */
export interface FontParts {
  style: string | null;
  weight: string | null;
  sizePx: number;
  family: string;
}

const FONT_RE =
  /^\s*((?:(?:italic|oblique|normal|small-caps|bold|bolder|lighter|\d{3})\s+)*)(\d*\.?\d+)px(?:\/\S+)?\s+(.+?)\s*$/;

/** Splits a canvas font shorthand ('italic 600 12px "Noto Sans", sans-serif') into style, weight, size and family; null if it is not one. */
export function parseFont(font: string): FontParts | null {
  const m = FONT_RE.exec(font);
  if (!m) return null;
  let style: string | null = null;
  let weight: string | null = null;
  for (const w of m[1].split(/\s+/)) {
    if (w === 'italic' || w === 'oblique') style = w;
    else if (/^\d{3}$/.test(w) || w === 'bold' || w === 'bolder' || w === 'lighter') weight = w;
  }
  return { style, weight, sizePx: Number(m[2]), family: m[3] };
}

const ANCHOR: Partial<Record<CanvasTextAlign, string>> = { center: 'middle', right: 'end', end: 'end' };
const BASELINE: Partial<Record<CanvasTextBaseline, string>> = {
  middle: 'central',
  top: 'text-before-edge',
  hanging: 'hanging',
  bottom: 'text-after-edge',
  ideographic: 'ideographic',
};

let measureCtx: DrawContext | null | undefined;

function defaultMeasure(text: string, font: string): number {
  if (measureCtx === undefined) {
    measureCtx = null;
    if (typeof OffscreenCanvas !== 'undefined') measureCtx = new OffscreenCanvas(1, 1).getContext('2d');
    else if (typeof document !== 'undefined') measureCtx = document.createElement('canvas').getContext('2d');
  }
  if (measureCtx) {
    measureCtx.font = font;
    return measureCtx.measureText(text).width;
  }
  return 0.6 * (parseFont(font)?.sizePx ?? 10) * [...text].length;
}

function attrs(a: Record<string, string | number | null>): string {
  let s = '';
  for (const [k, v] of Object.entries(a)) {
    if (v === null) continue;
    s += ` ${k}="${escapeXml(typeof v === 'number' ? num(v) : v)}"`;
  }
  return s;
}

/**
 * A 2D drawing context that records what is drawn as SVG elements instead of pixels: paths for strokes and
 * fills (coordinates already transformed, like the canvas does at call time), <text> for text, colours,
 * widths, dashes, caps, joins and opacity as attributes. It implements the DrawContext subset of the canvas
 * API, so drawLinkage draws into it unchanged; toSvg() returns the document. Arcs are exact under
 * transforms that keep right angles (translate, rotate, scale), which is all drawLinkage uses.
 */
export class SvgContext implements DrawContext {
  readonly width: number;
  readonly height: number;
  private readonly measure: MeasureFont;
  private readonly elements: string[] = [];
  private readonly stack: DrawState[] = [];
  // The canvas's initial state: black paint (a spec default, not a palette colour), 1 px lines, 10px sans-serif.
  private s: DrawState = {
    matrix: IDENTITY,
    fillStyle: 'black',
    strokeStyle: 'black',
    lineWidth: 1,
    lineCap: 'butt',
    lineJoin: 'miter',
    font: '10px sans-serif',
    textAlign: 'start',
    textBaseline: 'alphabetic',
    globalAlpha: 1,
    dash: [],
  };
  private d: string[] = [];
  private pen: { x: number; y: number } | null = null;
  private subpathStart: { x: number; y: number } | null = null;

  /** A context for a picture of width x height CSS pixels. Throws for a size that is not positive and finite. */
  constructor(width: number, height: number, options: SvgContextOptions = {}) {
    for (const [name, v] of [
      ['width', width],
      ['height', height],
    ] as const) {
      if (!(v > 0) || !Number.isFinite(v)) throw new Error(`${name} must be a positive finite size, got ${v}`);
    }
    this.width = width;
    this.height = height;
    this.measure = options.measure ?? defaultMeasure;
  }

  get fillStyle(): string {
    return this.s.fillStyle;
  }
  set fillStyle(v: string | CanvasGradient | CanvasPattern) {
    if (typeof v === 'string') this.s.fillStyle = v;
  }
  get strokeStyle(): string {
    return this.s.strokeStyle;
  }
  set strokeStyle(v: string | CanvasGradient | CanvasPattern) {
    if (typeof v === 'string') this.s.strokeStyle = v;
  }
  get lineWidth(): number {
    return this.s.lineWidth;
  }
  set lineWidth(v: number) {
    // The canvas ignores widths that are not positive and finite.
    if (v > 0 && Number.isFinite(v)) this.s.lineWidth = v;
  }
  get lineCap(): CanvasLineCap {
    return this.s.lineCap;
  }
  set lineCap(v: CanvasLineCap) {
    this.s.lineCap = v;
  }
  get lineJoin(): CanvasLineJoin {
    return this.s.lineJoin;
  }
  set lineJoin(v: CanvasLineJoin) {
    this.s.lineJoin = v;
  }
  get font(): string {
    return this.s.font;
  }
  set font(v: string) {
    if (parseFont(v)) this.s.font = v;
  }
  get textAlign(): CanvasTextAlign {
    return this.s.textAlign;
  }
  set textAlign(v: CanvasTextAlign) {
    this.s.textAlign = v;
  }
  get textBaseline(): CanvasTextBaseline {
    return this.s.textBaseline;
  }
  set textBaseline(v: CanvasTextBaseline) {
    this.s.textBaseline = v;
  }
  get globalAlpha(): number {
    return this.s.globalAlpha;
  }
  set globalAlpha(v: number) {
    if (v >= 0 && v <= 1) this.s.globalAlpha = v;
  }

  save(): void {
    this.stack.push({ ...this.s, dash: [...this.s.dash] });
  }
  restore(): void {
    const top = this.stack.pop();
    if (top) this.s = top;
  }
  translate(x: number, y: number): void {
    if (Number.isFinite(x) && Number.isFinite(y)) this.s.matrix = multiply(this.s.matrix, [1, 0, 0, 1, x, y]);
  }
  rotate(angleRad: number): void {
    if (!Number.isFinite(angleRad)) return;
    const c = Math.cos(angleRad);
    const s = Math.sin(angleRad);
    this.s.matrix = multiply(this.s.matrix, [c, s, -s, c, 0, 0]);
  }
  scale(x: number, y: number): void {
    if (Number.isFinite(x) && Number.isFinite(y)) this.s.matrix = multiply(this.s.matrix, [x, 0, 0, y, 0, 0]);
  }
  setLineDash(segments: Iterable<number>): void {
    const d = [...segments];
    // The canvas ignores a dash list with a negative or non-finite entry, and repeats an odd one twice.
    if (d.some((v) => !(v >= 0) || !Number.isFinite(v))) return;
    this.s.dash = d.length % 2 ? [...d, ...d] : d;
  }

  beginPath(): void {
    this.d = [];
    this.pen = null;
    this.subpathStart = null;
  }
  private point(x: number, y: number): { x: number; y: number } {
    const m = this.s.matrix;
    return { x: m[0] * x + m[2] * y + m[4], y: m[1] * x + m[3] * y + m[5] };
  }
  moveTo(x: number, y: number): void {
    if (!Number.isFinite(x) || !Number.isFinite(y)) return;
    const p = this.point(x, y);
    this.d.push(`M${num(p.x)} ${num(p.y)}`);
    this.pen = p;
    this.subpathStart = p;
  }
  lineTo(x: number, y: number): void {
    if (!Number.isFinite(x) || !Number.isFinite(y)) return;
    if (!this.pen) {
      this.moveTo(x, y);
      return;
    }
    const p = this.point(x, y);
    this.d.push(`L${num(p.x)} ${num(p.y)}`);
    this.pen = p;
  }
  closePath(): void {
    if (!this.pen || !this.subpathStart) return;
    this.d.push('Z');
    this.pen = this.subpathStart;
  }
  arc(x: number, y: number, radius: number, startRad: number, endRad: number, counterclockwise = false): void {
    if (![x, y, radius, startRad, endRad].every(Number.isFinite)) return;
    if (radius < 0) throw new Error(`arc radius must not be negative, got ${radius}`);
    const raw = counterclockwise ? startRad - endRad : endRad - startRad;
    const sweepRad = raw >= TWO_PI ? TWO_PI : ((raw % TWO_PI) + TWO_PI) % TWO_PI;
    const dir = counterclockwise ? -1 : 1;
    const at = (a: number) => ({ x: x + radius * Math.cos(a), y: y + radius * Math.sin(a) });
    const start = at(startRad);
    if (this.pen) this.lineTo(start.x, start.y);
    else this.moveTo(start.x, start.y);
    if (sweepRad === 0 || radius === 0) return;
    const m = this.s.matrix;
    const rx = radius * Math.hypot(m[0], m[1]);
    const ry = radius * Math.hypot(m[2], m[3]);
    const rotDeg = radToDeg(Math.atan2(m[1], m[0]));
    // SVG's sweep flag 1 turns the way positive angles go in its y-down frame, as the canvas's clockwise arc;
    // a mirroring transform turns it round.
    const det = m[0] * m[3] - m[1] * m[2];
    const sweepFlag = dir > 0 !== det < 0 ? 1 : 0;
    // Pieces of at most half a turn: an SVG arc whose ends meet (a full circle) draws nothing.
    const pieces = Math.max(1, Math.ceil(sweepRad / PI - 1e-12));
    for (let k = 1; k <= pieces; k++) {
      const e = this.point(...xy(at(startRad + (dir * sweepRad * k) / pieces)));
      this.d.push(`A${num(rx)} ${num(ry)} ${num(rotDeg)} 0 ${sweepFlag} ${num(e.x)} ${num(e.y)}`);
      this.pen = e;
    }
  }
  rect(x: number, y: number, w: number, h: number): void {
    if (![x, y, w, h].every(Number.isFinite)) return;
    this.moveTo(x, y);
    this.lineTo(x + w, y);
    this.lineTo(x + w, y + h);
    this.lineTo(x, y + h);
    this.closePath();
  }
  roundRect(x: number, y: number, w: number, h: number, radii = 0): void {
    if (![x, y, w, h, radii].every(Number.isFinite)) return;
    if (radii < 0) throw new Error(`roundRect radius must not be negative, got ${radii}`);
    const r = Math.min(radii, Math.abs(w) / 2, Math.abs(h) / 2);
    if (r === 0 || w < 0 || h < 0) {
      this.rect(x, y, w, h);
      return;
    }
    const q = PI / 2;
    this.moveTo(x + r, y);
    this.arc(x + w - r, y + r, r, -q, 0);
    this.arc(x + w - r, y + h - r, r, 0, q);
    this.arc(x + r, y + h - r, r, q, PI);
    this.arc(x + r, y + r, r, PI, 3 * q);
    this.closePath();
  }

  private lineWidthOut(): number {
    const m = this.s.matrix;
    return Math.sqrt(Math.abs(m[0] * m[3] - m[1] * m[2]));
  }
  private opacity(): number | null {
    return this.s.globalAlpha < 1 ? this.s.globalAlpha : null;
  }
  private strokeAttrs(): Record<string, string | number | null> {
    const k = this.lineWidthOut();
    return {
      stroke: this.s.strokeStyle,
      'stroke-width': this.s.lineWidth * k,
      'stroke-linecap': this.s.lineCap === 'butt' ? null : this.s.lineCap,
      'stroke-linejoin': this.s.lineJoin === 'miter' ? null : this.s.lineJoin,
      'stroke-dasharray': this.s.dash.length ? this.s.dash.map((v) => num(v * k)).join(' ') : null,
    };
  }
  stroke(): void {
    if (this.d.length === 0) return;
    this.elements.push(
      `<path${attrs({ d: this.d.join(''), fill: 'none', ...this.strokeAttrs(), opacity: this.opacity() })}/>`,
    );
  }
  fill(): void {
    if (this.d.length === 0) return;
    this.elements.push(`<path${attrs({ d: this.d.join(''), fill: this.s.fillStyle, opacity: this.opacity() })}/>`);
  }
  fillRect(x: number, y: number, w: number, h: number): void {
    // Its own path: fillRect leaves the current path alone.
    const saved = { d: this.d, pen: this.pen, start: this.subpathStart };
    this.beginPath();
    this.rect(x, y, w, h);
    this.fill();
    this.d = saved.d;
    this.pen = saved.pen;
    this.subpathStart = saved.start;
  }

  private text(text: string, x: number, y: number, paint: Record<string, string | number | null>): void {
    if (!Number.isFinite(x) || !Number.isFinite(y)) return;
    const f = parseFont(this.s.font);
    const m = this.s.matrix;
    const plain = m[0] === 1 && m[1] === 0 && m[2] === 0 && m[3] === 1;
    const p = plain ? this.point(x, y) : { x, y };
    const a = attrs({
      x: p.x,
      y: p.y,
      transform: plain ? null : `matrix(${m.map(num).join(' ')})`,
      'font-family': f ? f.family : null,
      'font-size': f ? f.sizePx : null,
      'font-weight': f?.weight ?? null,
      'font-style': f?.style ?? null,
      'text-anchor': ANCHOR[this.s.textAlign] ?? null,
      'dominant-baseline': BASELINE[this.s.textBaseline] ?? null,
      ...paint,
      opacity: this.opacity(),
    });
    this.elements.push(`<text${a}>${escapeXml(text)}</text>`);
  }
  fillText(text: string, x: number, y: number): void {
    this.text(text, x, y, { fill: this.s.fillStyle });
  }
  strokeText(text: string, x: number, y: number): void {
    this.text(text, x, y, { fill: 'none', ...this.strokeAttrs() });
  }
  measureText(text: string): { width: number } {
    return { width: this.measure(text, this.s.font) };
  }

  /** The SVG document drawn so far: an <svg> of width x height with a viewBox in CSS pixels. */
  toSvg(): string {
    const root = attrs({
      xmlns: 'http://www.w3.org/2000/svg',
      width: this.width,
      height: this.height,
      viewBox: `0 0 ${num(this.width)} ${num(this.height)}`,
    });
    return `<svg${root}>\n${this.elements.join('\n')}\n</svg>\n`;
  }
}

function xy(p: { x: number; y: number }): [number, number] {
  return [p.x, p.y];
}

/** A new SVG element outside the document, for off-screen chart rendering. */
export function detachedSvg(): SVGSVGElement {
  return document.createElementNS('http://www.w3.org/2000/svg', 'svg');
}
