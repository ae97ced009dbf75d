import { describe, expect, it } from 'vitest';
import { drawLinkage } from '../../../src/shared/linkage/drawLinkage';
import type { LinkageScene } from '../../../src/shared/linkage/scene';
import { THEME } from '../../../src/shared/canvas/canvasTheme';
import { fitView } from '../../../src/shared/canvas/view';
import { LINKAGES, RecordingContext, sweepScenes } from './fixtures';

// WCAG 2.x contrast of what drawLinkage actually paints: every fillText colour against what it sits on must
// reach 4.5:1 (1.4.3) and every stroked line 3:1 against the canvas (1.4.11). Labels sit on the canvas (never
// on the warning box: sceneLayout.test.ts), the warning's two lines on the warning box's fill. The colours come from recording the drawing calls, so a new hard-coded colour
// in drawLinkage is checked too.

/** sRGB channels 0..255 and alpha 0..1 of a #rgb, #rrggbb or rgb()/rgba() colour. */
function parseColor(c: string): [number, number, number, number] {
  const s = c.trim().toLowerCase();
  let m = /^#([0-9a-f]{3})$/.exec(s);
  if (m) return [...[...m[1]].map((h) => parseInt(h + h, 16)), 1] as [number, number, number, number];
  m = /^#([0-9a-f]{6})$/.exec(s);
  if (m) return [0, 2, 4].map((i) => parseInt(m![1].slice(i, i + 2), 16)).concat(1) as [number, number, number, number];
  m = /^rgba?\(\s*([\d.]+)\s*,\s*([\d.]+)\s*,\s*([\d.]+)\s*(?:,\s*([\d.]+)\s*)?\)$/.exec(s);
  if (m) return [Number(m[1]), Number(m[2]), Number(m[3]), m[4] === undefined ? 1 : Number(m[4])];
  throw new Error(`cannot parse colour ${c}`);
}

/** fg painted over an opaque bg (alpha compositing in sRGB, as canvas does). */
function over(fg: string, bg: [number, number, number]): [number, number, number] {
  const [r, g, b, a] = parseColor(fg);
  return [r * a + bg[0] * (1 - a), g * a + bg[1] * (1 - a), b * a + bg[2] * (1 - a)];
}

/** WCAG relative luminance of an sRGB colour (channels 0..255). */
function luminance([r, g, b]: [number, number, number]): number {
  const lin = (v: number) => {
    const c = v / 255;
    return c <= 0.03928 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
  };
  return 0.2126 * lin(r) + 0.7152 * lin(g) + 0.0722 * lin(b);
}

/** WCAG contrast ratio of two opaque colours, 1..21. */
function ratio(a: [number, number, number], b: [number, number, number]): number {
  const [hi, lo] = [luminance(a), luminance(b)].sort((x, y) => y - x);
  return (hi + 0.05) / (lo + 0.05);
}

const BACKGROUND = over(THEME.background, [255, 255, 255]);
const WARNING_BG = over(THEME.warningFill, BACKGROUND);

/** Lines exempt from 3:1, with the reason: the grid and its axes are a faint backdrop, not content. */
const DECORATIVE_LINES = new Set<string>([THEME.grid, THEME.gridAxis]);

function recordAll(): { ctx: RecordingContext; warningTexts: Set<string> } {
  const ctx = new RecordingContext();
  const warningTexts = new Set<string>();
  const scenes: LinkageScene[] = [];
  for (const t of [LINKAGES[0], LINKAGES[5]]) {
    for (const s of sweepScenes(t, 'open', 'en', 15)) {
      // One current and one other-circuit coupler curve, so both trace colours are drawn.
      scenes.push({
        ...s,
        curves: [
          { x: [0, 1, 2], y: [1, 2, 1], current: true },
          { x: [0, 1, 2], y: [-1, -2, -1], current: false },
        ],
      });
    }
  }
  expect(scenes.some((s) => s.pose === null)).toBe(true);
  for (const s of scenes) {
    for (const w of [s.text.warning, s.text.warningDetail]) if (w) warningTexts.add(w);
    drawLinkage(
      ctx as unknown as CanvasRenderingContext2D,
      s,
      fitView(s.bounds, 640, 400, { zoom: 1, panX: 0, panY: 0 }),
    );
  }
  return { ctx, warningTexts };
}

describe('canvas contrast', () => {
  const { ctx, warningTexts } = recordAll();

  it('reads every canvas text at 4.5:1 or more on what it sits on', () => {
    const texts = new Map<string, number>();
    for (const c of ctx.calls) {
      if (c.op !== 'fillText') continue;
      const bg = warningTexts.has(c.text!) ? WARNING_BG : BACKGROUND;
      const key = `${c.fillStyle} on ${bg === BACKGROUND ? 'canvas' : 'warning'}`;
      texts.set(key, Math.min(texts.get(key) ?? Infinity, ratio(over(c.fillStyle, bg), bg)));
    }
    // Joint names, link names r1..r4, angle labels, the grid label, the warning and its detail.
    expect(texts.size).toBeGreaterThanOrEqual(9);
    for (const [color, r] of texts) expect(r, color).toBeGreaterThanOrEqual(4.5);
  });

  it('draws every line but the grid at 3:1 or more against the canvas', () => {
    const lines = new Map<string, number>();
    for (const c of ctx.calls) {
      if (c.op !== 'stroke' || DECORATIVE_LINES.has(c.strokeStyle)) continue;
      lines.set(c.strokeStyle, ratio(over(c.strokeStyle, BACKGROUND), BACKGROUND));
    }
    // Links, ground, trace and its other circuits, the ghost branch, arcs, references, joint outlines, warning.
    expect(lines.size).toBeGreaterThanOrEqual(10);
    for (const [color, r] of lines) expect(r, `line ${color}`).toBeGreaterThanOrEqual(3);
  });

  it('gives labels a halo of the background colour', () => {
    const halos = new Set(ctx.calls.filter((c) => c.op === 'strokeText').map((c) => c.strokeStyle));
    expect([...halos]).toEqual([THEME.labelHalo]);
    expect(ratio(over(THEME.labelHalo, BACKGROUND), BACKGROUND)).toBeLessThan(1.05);
  });
});

describe('ratio (the oracle)', () => {
  it('matches the WCAG reference values', () => {
    expect(ratio([0, 0, 0], [255, 255, 255])).toBeCloseTo(21, 10);
    expect(ratio([255, 255, 255], [255, 255, 255])).toBe(1);
    // #767676 on white is the well-known 4.54:1 grey.
    expect(ratio(over('#767676', [255, 255, 255]), [255, 255, 255])).toBeCloseTo(4.54, 2);
  });
});
