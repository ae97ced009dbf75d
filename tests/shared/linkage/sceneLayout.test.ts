import { beforeAll, describe, expect, it } from 'vitest';
import { canvasToolsRect } from '../../../src/shared/canvas/canvasTools';
import { drawLinkage } from '../../../src/shared/linkage/drawLinkage';
import type { Px, ScreenRect } from '../../../src/shared/canvas/rect';
import type { LabelId, SceneLayout } from '../../../src/shared/linkage/sceneLayout';
import { layoutScene } from '../../../src/shared/linkage/sceneLayout';
import { fitView } from '../../../src/shared/canvas/view';
import { FONT_SIZES } from '../../../src/shared/theme/tokens';
import type { Branch } from '../../../src/solver/types';
import { LINKAGES, RecordingContext, measureModel, sweepScenes } from './fixtures';

// The label placement over a dense sweep: every 1 degree of theta2, both branches, six linkages (the report's
// 6-2-5-5, a drag link, a parallelogram, a near-toggle crank-rocker, a tiny crank, a triple rocker that cannot
// assemble everywhere), three canvas sizes and two languages: 25 920 layouts. The geometry checks below use
// their own overlap and distance functions, not the module's.

/** Canvas sizes in CSS pixels: the laptop stage, a 390-wide phone's stage, the 600x450 embed's stage. */
const SIZES = [
  { name: 'laptop', width: 652, height: 368 },
  { name: 'phone', width: 372, height: 330 },
  { name: 'embed 600x450', width: 342, height: 392 },
] as const;

const JOINTS = ['O2', 'O4', 'A', 'B', 'P'] as const;

interface Case {
  where: string;
  width: number;
  height: number;
  tools: ScreenRect;
  layout: SceneLayout;
}

let cases: Case[] = [];

beforeAll(() => {
  cases = [];
  for (const t of LINKAGES) {
    for (const branch of ['open', 'crossed'] as Branch[]) {
      for (const lang of ['en', 'zh-TW'] as const) {
        const scenes = sweepScenes(t, branch, lang);
        for (const size of SIZES) {
          const tools = canvasToolsRect(size.width);
          scenes.forEach((scene, deg) => {
            const view = fitView(scene.bounds, size.width, size.height, { zoom: 1, panX: 0, panY: 0 });
            cases.push({
              where: `${t.name}, ${branch}, ${lang}, ${size.name}, θ2 = ${deg}°`,
              width: size.width,
              height: size.height,
              tools,
              layout: layoutScene(scene, view, measureModel, [tools]),
            });
          });
        }
      }
    }
  }
  // About 25 000 layouts: seconds on an idle machine, more on a busy one.
}, 180_000);

/** Area shared by two boxes (0 when they only touch). */
function overlapArea(a: ScreenRect, b: ScreenRect): number {
  const w = Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x);
  const h = Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y);
  return w > 1e-9 && h > 1e-9 ? w * h : 0;
}

/** Distance (CSS pixels) from p to the nearest point of box r (0 inside). */
function distanceToBox(p: Px, r: ScreenRect): number {
  const dx = Math.max(r.x - p.x, 0, p.x - (r.x + r.width));
  const dy = Math.max(r.y - p.y, 0, p.y - (r.y + r.height));
  return Math.hypot(dx, dy);
}

/** Distance from segment a-b to box r, by 51 samples along the segment (within 1 % of its length). */
function segmentToBox(a: Px, b: Px, r: ScreenRect): number {
  let best = Infinity;
  for (let i = 0; i <= 50; i++) {
    const t = i / 50;
    best = Math.min(best, distanceToBox({ x: a.x + (b.x - a.x) * t, y: a.y + (b.y - a.y) * t }, r));
  }
  return best;
}

function boxesOf(layout: SceneLayout): { id: string; box: ScreenRect }[] {
  const out: { id: string; box: ScreenRect }[] = layout.labels.map((l) => ({ id: l.id, box: l.box }));
  if (layout.warning) out.push({ id: 'warning', box: layout.warning.box });
  return out;
}

describe('layoutScene', () => {
  it('covers the whole sweep, including poses that cannot assemble', () => {
    expect(cases.length).toBe(6 * 2 * 2 * 3 * 360);
    expect(cases.filter((c) => c.layout.warning).length).toBeGreaterThan(100);
  });

  it('never overlaps two labels (or the warning), the zoom buttons or the canvas edge', () => {
    const faults: string[] = [];
    for (const c of cases) {
      const boxes = boxesOf(c.layout);
      for (let i = 0; i < boxes.length; i++) {
        const b = boxes[i].box;
        if (overlapArea(b, c.tools) > 0) faults.push(`${c.where}: ${boxes[i].id} under the zoom buttons`);
        if (b.x < 0 || b.y < 0 || b.x + b.width > c.width || b.y + b.height > c.height)
          faults.push(`${c.where}: ${boxes[i].id} leaves the canvas`);
        for (let j = i + 1; j < boxes.length; j++)
          if (overlapArea(b, boxes[j].box) > 0) faults.push(`${c.where}: ${boxes[i].id} overlaps ${boxes[j].id}`);
      }
    }
    expect(faults.slice(0, 10)).toEqual([]);
  });

  it('gives each label a box that holds its text: the measured width and the font size, plus the halo', () => {
    const faults: string[] = [];
    for (const c of cases.filter((_, i) => i % 7 === 0)) {
      for (const l of c.layout.labels) {
        const fontPx = l.font === 'bold' ? FONT_SIZES.canvasBold : FONT_SIZES.canvas;
        // The white halo is stroked 3 px wide: 1.5 px beyond the glyphs on each side.
        if (l.box.width < measureModel(l.text, l.font) + 3 || l.box.height < fontPx + 3)
          faults.push(`${c.where}: ${l.id} box ${l.box.width}x${l.box.height}`);
        expect(l.centre.x).toBeCloseTo(l.box.x + l.box.width / 2, 9);
        expect(l.centre.y).toBeCloseTo(l.box.y + l.box.height / 2, 9);
      }
    }
    expect(faults.slice(0, 10)).toEqual([]);
  });

  it('names every joint in every pose, within 32 px of the joint', () => {
    const faults: string[] = [];
    for (const c of cases) {
      for (const id of JOINTS) {
        const at = c.layout.joints[id];
        if (!at) continue;
        const label = c.layout.labels.find((l) => l.id === id);
        // The farthest candidate ring: 24 px beyond a clearance of the joint radius (5 or 6 px) plus 2.
        if (!label) faults.push(`${c.where}: ${id} dropped`);
        else if (distanceToBox(at, label.box) > 32 + 1e-9)
          faults.push(`${c.where}: ${id} ${distanceToBox(at, label.box).toFixed(1)} px from its joint`);
      }
    }
    expect(faults.slice(0, 10)).toEqual([]);
  });

  it('puts each angle label within 18 px outside its arc and each link label within 31 px of its link', () => {
    const faults: string[] = [];
    for (const c of cases) {
      const j = c.layout.joints;
      for (const l of c.layout.labels) {
        const arc = c.layout.arcs.find((a) => a.color === l.color);
        if (l.id.startsWith('theta') || l.id === 'mu') {
          if (!arc) faults.push(`${c.where}: ${l.id} without its arc`);
          else if (distanceToBox(arc.centre, l.box) > arc.radiusPx + 18 + 1e-6)
            faults.push(`${c.where}: ${l.id} far from its arc`);
        }
        const link: Partial<Record<LabelId, [Px | null, Px | null]>> = {
          r1: [j.O2, j.O4],
          r2: [j.O2, j.A],
          r3: [j.A, j.B],
          r4: [j.B, j.O4],
        };
        const seg = link[l.id];
        // Largest gap 28 px beyond half the link width (2.5 px), plus the 1 % sampling of the segment.
        if (
          seg &&
          seg[0] &&
          seg[1] &&
          segmentToBox(seg[0], seg[1], l.box) > 31 + 0.01 * Math.hypot(seg[1].x - seg[0].x, seg[1].y - seg[0].y)
        )
          faults.push(`${c.where}: ${l.id} far from its link`);
      }
    }
    expect(faults.slice(0, 10)).toEqual([]);
  });

  it('drops no label at all, except the link name r2 of the tiny crank in a few poses (its crank is 2 px long)', () => {
    const dropped = new Map<string, number>();
    for (const c of cases) {
      for (const id of c.layout.dropped) {
        const key = `${c.where.split(',')[0]}: ${id}`;
        dropped.set(key, (dropped.get(key) ?? 0) + 1);
      }
    }
    const tinyR2 = dropped.get('tiny crank: r2') ?? 0;
    dropped.delete('tiny crank: r2');
    expect(Object.fromEntries(dropped)).toEqual({});
    expect(tinyR2 / cases.filter((c) => c.where.startsWith('tiny crank')).length).toBeLessThan(0.05);
  });

  it('sets half the joint names right beside their joint (within 10 px)', () => {
    const d: number[] = [];
    for (const c of cases) {
      for (const l of c.layout.labels) {
        const at = (JOINTS as readonly string[]).includes(l.id)
          ? c.layout.joints[l.id as (typeof JOINTS)[number]]
          : null;
        if (at) d.push(distanceToBox(at, l.box));
      }
    }
    d.sort((a, b) => a - b);
    // The first ring of candidates: the joint radius (5 or 6 px), a 2 px clearance and a 2 px gap.
    expect(d[Math.floor(d.length / 2)]).toBeLessThanOrEqual(10);
  });

  it('keeps the warning box clear of the zoom buttons on a narrow canvas', () => {
    const warned = cases.filter((c) => c.layout.warning && c.width < 400);
    expect(warned.length).toBeGreaterThan(0);
    for (const c of warned) expect(overlapArea(c.layout.warning!.box, c.tools)).toBe(0);
  });
});

describe('drawLinkage', () => {
  it('draws each label, in its colour, at the centre layoutScene placed it', () => {
    const t = LINKAGES[0];
    for (const scene of sweepScenes(t, 'open', 'en', 30)) {
      const view = fitView(scene.bounds, 652, 368, { zoom: 1, panX: 0, panY: 0 });
      const ctx = new RecordingContext();
      const drawn = drawLinkage(ctx as unknown as CanvasRenderingContext2D, scene, view, [canvasToolsRect(652)]);
      const expected = layoutScene(scene, view, measureModel, [canvasToolsRect(652)]);
      expect(drawn).toEqual(expected);
      const texts = ctx.calls.filter((c) => c.op === 'fillText');
      expect(texts.length).toBe(expected.labels.length);
      for (const l of expected.labels) {
        const call = texts.find((c) => c.text === l.text);
        expect(call, l.text).toBeDefined();
        expect(call!.x).toBeCloseTo(l.centre.x, 9);
        expect(call!.y).toBeCloseTo(l.centre.y, 9);
        expect(call!.fillStyle).toBe(l.color);
      }
    }
  });
});
