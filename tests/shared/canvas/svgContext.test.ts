import { describe, expect, it } from 'vitest';
import { drawLinkage } from '../../../src/shared/linkage/drawLinkage';
import type { DrawContext } from '../../../src/shared/canvas/drawContext';
import { SvgContext, escapeXml, parseFont } from '../../../src/shared/canvas/svgContext';
import { fitView } from '../../../src/shared/canvas/view';
import { LINKAGES, RecordingContext, measureModel, sweepScenes } from '../linkage/fixtures';

// Coordinates are written with 3 decimals: compare to 1e-3 CSS pixel.
const PX_TOL = 1e-3;

/** The elements of an SVG string: tag name, attributes and text content (a flat regex read, enough for SvgContext's output). */
function elements(svg: string): { tag: string; attrs: Record<string, string>; text: string }[] {
  const out: { tag: string; attrs: Record<string, string>; text: string }[] = [];
  for (const m of svg.matchAll(/<(path|text)((?:\s+[\w-]+="[^"]*")*)\s*(?:\/>|>([^<]*)<\/\1>)/g)) {
    const attrs: Record<string, string> = {};
    for (const a of m[2].matchAll(/([\w-]+)="([^"]*)"/g)) attrs[a[1]] = a[2];
    out.push({ tag: m[1], attrs, text: m[3] ?? '' });
  }
  return out;
}

/** The end points of a path's commands (M, L, A; Z returns to the subpath start), as numbers. */
function pathPoints(d: string): { cmd: string; x: number; y: number; args: number[] }[] {
  const pts: { cmd: string; x: number; y: number; args: number[] }[] = [];
  for (const m of d.matchAll(/([MLAZ])([^MLAZ]*)/g)) {
    const args = m[2].trim() ? m[2].trim().split(/\s+/).map(Number) : [];
    if (m[1] === 'Z') continue;
    pts.push({ cmd: m[1], x: args[args.length - 2], y: args[args.length - 1], args });
  }
  return pts;
}

const unescape = (s: string) =>
  s
    .replace(/&lt;/g, '<')
    .replace(/&gt;/g, '>')
    .replace(/&quot;/g, '"')
    .replace(/&apos;/g, "'")
    .replace(/&amp;/g, '&');

const fixedMeasure = (text: string) => 7 * text.length;

describe('SvgContext', () => {
  it('writes a full circle as two half-turn arcs through the opposite point, clockwise', () => {
    const ctx = new SvgContext(100, 100, { measure: fixedMeasure });
    ctx.beginPath();
    ctx.arc(10, 20, 5, 0, 2 * Math.PI);
    ctx.stroke();
    const [p] = elements(ctx.toSvg());
    const pts = pathPoints(p.attrs.d);
    expect(pts.map((q) => q.cmd)).toEqual(['M', 'A', 'A']);
    expect([pts[0].x, pts[0].y]).toEqual([15, 20]);
    expect(pts[1].x).toBeCloseTo(5, 3);
    expect(pts[1].y).toBeCloseTo(20, 3);
    expect([pts[2].x, pts[2].y]).toEqual([15, 20]);
    // rx ry rotation large-arc sweep: radius 5, sweep 1 (the canvas's clockwise in y-down).
    expect(pts[1].args.slice(0, 5)).toEqual([5, 5, 0, 0, 1]);
  });

  it('ends a counter-clockwise quarter arc at the angle given, with sweep flag 0', () => {
    const ctx = new SvgContext(100, 100, { measure: fixedMeasure });
    ctx.beginPath();
    ctx.arc(50, 50, 10, 0, -Math.PI / 2, true);
    ctx.stroke();
    const pts = pathPoints(elements(ctx.toSvg())[0].attrs.d);
    expect(pts).toHaveLength(2);
    expect(pts[1].x).toBeCloseTo(50 + 10 * Math.cos(-Math.PI / 2), 3);
    expect(pts[1].y).toBeCloseTo(50 + 10 * Math.sin(-Math.PI / 2), 3);
    expect(pts[1].args[4]).toBe(0);
  });

  it('turns the sweep round under a mirroring transform (y up)', () => {
    const ctx = new SvgContext(100, 100, { measure: fixedMeasure });
    ctx.translate(0, 100);
    ctx.scale(1, -1);
    ctx.beginPath();
    ctx.arc(50, 50, 10, 0, Math.PI / 2);
    ctx.stroke();
    const pts = pathPoints(elements(ctx.toSvg())[0].attrs.d);
    // World (50, 60) lands at (50, 40) on the page; the clockwise canvas arc is counter-clockwise there.
    expect(Math.abs(pts[1].x - 50)).toBeLessThan(PX_TOL);
    expect(Math.abs(pts[1].y - 40)).toBeLessThan(PX_TOL);
    expect(pts[1].args[4]).toBe(0);
  });

  it('joins an arc to the current point with a line, as the canvas does', () => {
    const ctx = new SvgContext(100, 100, { measure: fixedMeasure });
    ctx.beginPath();
    ctx.moveTo(0, 0);
    ctx.arc(50, 50, 10, Math.PI, 1.5 * Math.PI);
    ctx.stroke();
    const pts = pathPoints(elements(ctx.toSvg())[0].attrs.d);
    expect(pts.map((q) => q.cmd)).toEqual(['M', 'L', 'A']);
    expect([pts[1].x, pts[1].y]).toEqual([40, 50]);
  });

  it('applies translate, scale and rotate to points, line widths and dashes at call time', () => {
    const ctx = new SvgContext(200, 200, { measure: fixedMeasure });
    ctx.translate(100, 50);
    ctx.scale(2, 2);
    ctx.rotate(Math.PI / 2);
    ctx.lineWidth = 1.5;
    ctx.setLineDash([3, 1]);
    ctx.beginPath();
    ctx.moveTo(0, 0);
    ctx.lineTo(10, 0);
    ctx.stroke();
    const [p] = elements(ctx.toSvg());
    const pts = pathPoints(p.attrs.d);
    // (10, 0) rotated a quarter turn (y down) is (0, 10), scaled 2, moved by (100, 50).
    expect(Math.abs(pts[1].x - 100)).toBeLessThan(PX_TOL);
    expect(Math.abs(pts[1].y - 70)).toBeLessThan(PX_TOL);
    expect(Number(p.attrs['stroke-width'])).toBeCloseTo(3, 9);
    expect(p.attrs['stroke-dasharray']).toBe('6 2');
  });

  it('restores styles and the transform with restore', () => {
    const ctx = new SvgContext(100, 100, { measure: fixedMeasure });
    ctx.strokeStyle = '#ff0000';
    ctx.save();
    ctx.strokeStyle = '#00ff00';
    ctx.translate(10, 10);
    ctx.restore();
    ctx.beginPath();
    ctx.moveTo(1, 2);
    ctx.lineTo(3, 4);
    ctx.stroke();
    const [p] = elements(ctx.toSvg());
    expect(p.attrs.stroke).toBe('#ff0000');
    expect(p.attrs.d).toBe('M1 2L3 4');
  });

  it('ignores non-finite coordinates, as the canvas does', () => {
    const ctx = new SvgContext(100, 100, { measure: fixedMeasure });
    ctx.beginPath();
    ctx.moveTo(1, 1);
    ctx.lineTo(Number.NaN, 5);
    ctx.lineTo(2, 2);
    ctx.stroke();
    expect(elements(ctx.toSvg())[0].attrs.d).toBe('M1 1L2 2');
  });

  it('keeps the current path through fillRect', () => {
    const ctx = new SvgContext(100, 100, { measure: fixedMeasure });
    ctx.beginPath();
    ctx.moveTo(1, 1);
    ctx.fillRect(0, 0, 5, 5);
    ctx.lineTo(2, 2);
    ctx.stroke();
    const els = elements(ctx.toSvg());
    expect(els.map((e) => e.tag)).toEqual(['path', 'path']);
    expect(els[1].attrs.d).toBe('M1 1L2 2');
  });

  it('writes text as <text>, escaped, with the font split into attributes and the alignment mapped', () => {
    const ctx = new SvgContext(100, 100, { measure: fixedMeasure });
    ctx.font = '600 12px system-ui, "Segoe UI", sans-serif';
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.fillStyle = '#123456';
    const nasty = `<b> & "θ2" 's`;
    ctx.fillText(nasty, 20, 30);
    const svg = ctx.toSvg();
    expect(svg).not.toContain('<b>');
    const [t] = elements(svg);
    expect(t.tag).toBe('text');
    expect(unescape(t.text)).toBe(nasty);
    expect(t.attrs).toMatchObject({
      x: '20',
      y: '30',
      fill: '#123456',
      'font-weight': '600',
      'font-size': '12',
      'text-anchor': 'middle',
      'dominant-baseline': 'central',
    });
    expect(unescape(t.attrs['font-family'])).toBe('system-ui, "Segoe UI", sans-serif');
  });

  it('draws stroked text as an outline with no fill', () => {
    const ctx = new SvgContext(100, 100, { measure: fixedMeasure });
    ctx.lineWidth = 3;
    ctx.strokeStyle = '#ffffff';
    ctx.lineJoin = 'round';
    ctx.strokeText('A', 5, 5);
    const [t] = elements(ctx.toSvg());
    expect(t.attrs).toMatchObject({ fill: 'none', stroke: '#ffffff', 'stroke-width': '3', 'stroke-linejoin': 'round' });
  });

  it('measures text with the given measure in the current font', () => {
    const seen: string[] = [];
    const ctx = new SvgContext(100, 100, { measure: (t, f) => (seen.push(f), t.length) });
    ctx.font = '11px serif';
    expect(ctx.measureText('abcd').width).toBe(4);
    expect(seen).toEqual(['11px serif']);
  });

  it('rejects a size that is not positive', () => {
    expect(() => new SvgContext(0, 10)).toThrow(/width must be a positive finite size, got 0/);
  });
});

describe('escapeXml', () => {
  it('escapes the five XML specials and nothing else', () => {
    expect(escapeXml(`a&b<c>d"e'f θ`)).toBe('a&amp;b&lt;c&gt;d&quot;e&apos;f θ');
  });
});

describe('parseFont', () => {
  it('splits a canvas font shorthand', () => {
    expect(parseFont('italic bold 13.5px "Noto Sans TC", sans-serif')).toEqual({
      style: 'italic',
      weight: 'bold',
      sizePx: 13.5,
      family: '"Noto Sans TC", sans-serif',
    });
    expect(parseFont('not a font')).toBeNull();
  });
});

describe('drawLinkage into SvgContext', () => {
  it('writes every label the canvas draws as <text> at the same place, in the same colour', () => {
    for (const t of LINKAGES) {
      const scene = sweepScenes(t, 'open', 'en', 45)[1];
      const view = fitView(scene.bounds, 640, 400, { zoom: 1, panX: 0, panY: 0 });
      const rec = new RecordingContext();
      drawLinkage(rec as unknown as DrawContext, scene, view);
      const svg = new SvgContext(640, 400, {
        measure: (text, font) => measureModel(text, /^(600|bold)\b/.test(font) ? 'bold' : 'regular'),
      });
      drawLinkage(svg, scene, view);
      const texts = elements(svg.toSvg()).filter((e) => e.tag === 'text' && e.attrs.fill !== 'none');
      const fills = rec.calls.filter((c) => c.op === 'fillText');
      expect(
        texts.map((e) => unescape(e.text)),
        t.name,
      ).toEqual(fills.map((c) => c.text));
      texts.forEach((e, i) => {
        expect(Math.abs(Number(e.attrs.x) - fills[i].x!)).toBeLessThan(PX_TOL);
        expect(Math.abs(Number(e.attrs.y) - fills[i].y!)).toBeLessThan(PX_TOL);
        expect(e.attrs.fill).toBe(fills[i].fillStyle);
      });
      if (scene.pose) for (const j of ['O2', 'O4', 'A', 'B', 'P']) expect(texts.map((e) => e.text)).toContain(j);
      // Every stroke and fill the canvas makes is one SVG path (fillRect included).
      const paths = elements(svg.toSvg()).filter((e) => e.tag === 'path');
      expect(paths.length).toBe(rec.calls.filter((c) => c.op !== 'fillText' && c.op !== 'strokeText').length);
    }
  });
});
