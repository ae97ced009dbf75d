import { describe, expect, it } from 'vitest';
import {
  ARROW_MAX_PX,
  ARROW_MIN_PX,
  ARROW_TARGET_PX,
  arrowLength,
  arrowScale,
  vectorOverlay,
} from '../../../src/shared/linkage/motionVectors';
import type { SceneVectors, VectorText } from '../../../src/shared/linkage/motionVectors';
import type { LinkageScene } from '../../../src/shared/linkage/scene';
import { layoutScene } from '../../../src/shared/linkage/sceneLayout';
import { drawLinkage } from '../../../src/shared/linkage/drawLinkage';
import { fitView } from '../../../src/shared/canvas/view';
import { RecordingContext, measureModel, reportScene } from './fixtures';

const TEXT: VectorText = {
  symbol: { v: 'v', a: 'a' },
  velocityBar: (v) => `= ${v} length/s`,
  accelerationBar: (v) => `= ${v} length/s²`,
  zero: 'zero',
  clamped: 'dashed: clamped',
  limit: 'limit position',
  formatValue: (x) => String(x),
};

describe('arrowScale', () => {
  it('shows the largest 1-2-5 value not above the typical magnitude, drawn at its share of the target length', () => {
    const cases: [number, number][] = [
      [20, 20],
      [7.3, 5],
      [1.9, 1],
      [0.034, 0.02],
      [999, 500],
    ];
    for (const [typical, value] of cases) {
      const s = arrowScale(typical);
      if (!s) throw new Error('no scale');
      expect(s.value).toBeCloseTo(value, 12);
      expect(s.pxPerUnit).toBeCloseTo(ARROW_TARGET_PX / typical, 12);
      expect(s.barPx).toBeCloseTo((value / typical) * ARROW_TARGET_PX, 9);
      // The bar is at least 40 % of the target (a 1-2-5 step is at most 2.5x) and never longer than it.
      expect(s.barPx).toBeGreaterThanOrEqual(0.4 * ARROW_TARGET_PX - 1e-9);
      expect(s.barPx).toBeLessThanOrEqual(ARROW_TARGET_PX + 1e-9);
    }
  });
  it('has no scale for zero or non-finite motion', () => {
    expect(arrowScale(0)).toBeNull();
    expect(arrowScale(Number.NaN)).toBeNull();
    expect(arrowScale(Number.POSITIVE_INFINITY)).toBeNull();
  });
});

describe('arrowLength', () => {
  it('draws to scale between the limits', () => {
    expect(arrowLength(10, 3)).toEqual({ lengthPx: 30, clamp: 'none' });
  });
  it('lengthens a tiny arrow to the shortest readable length and says so', () => {
    expect(arrowLength(1e-9, 3)).toEqual({ lengthPx: ARROW_MIN_PX, clamp: 'short' });
  });
  it('cuts a huge arrow to the longest length and says so', () => {
    expect(arrowLength(1e12, 3)).toEqual({ lengthPx: ARROW_MAX_PX, clamp: 'long' });
  });
  it('draws nothing for a zero or undetermined vector', () => {
    expect(arrowLength(0, 3)).toBeNull();
    expect(arrowLength(Number.NaN, 3)).toBeNull();
  });
});

/** A scene of the report's linkage at theta2 with the given vectors. */
function sceneWith(theta2Deg: number, vectors: SceneVectors): LinkageScene {
  return reportScene(theta2Deg, { vectors });
}

const V = { A: { x: -14, y: 14 }, B: { x: 0.3, y: -0.05 }, P: { x: 5, y: 11 } };
const ACC = { A: { x: -200, y: -200 }, B: { x: 1e6, y: 0 }, P: { x: -150, y: 40 } };

describe('vectorOverlay', () => {
  const vectors: SceneVectors = {
    velocity: V,
    acceleration: ACC,
    velocityScale: arrowScale(20),
    accelerationScale: arrowScale(200),
    limit: false,
    text: TEXT,
  };
  const scene = sceneWith(45, vectors);
  const view = fitView(scene.bounds, 640, 420, { zoom: 1, panX: 0, panY: 0 });
  const o = vectorOverlay(vectors, scene.pose, view, measureModel);

  it('puts an arrow at A, B and P of each kind, along the vector on screen (y down)', () => {
    expect(o.arrows.map((a) => `${a.kind}${a.at}`)).toEqual(['vA', 'vB', 'vP', 'aA', 'aB', 'aP']);
    const vP = o.arrows[2];
    const dx = vP.to.x - vP.from.x;
    const dy = vP.to.y - vP.from.y;
    // Same direction as (5, 11) with y flipped: cross product zero, dot product positive.
    expect(Math.abs(dx * -11 - dy * 5)).toBeLessThan(1e-9 * Math.hypot(dx, dy) * 12.1);
    expect(dx * 5 + dy * -11).toBeGreaterThan(0);
  });
  it('clamps the tiny and the huge arrow, dashes them and says so in the legend', () => {
    const vB = o.arrows.find((a) => a.kind === 'v' && a.at === 'B');
    const aB = o.arrows.find((a) => a.kind === 'a' && a.at === 'B');
    expect(vB?.clamp).toBe('short');
    expect(aB?.clamp).toBe('long');
    expect(Math.hypot(aB!.to.x - aB!.from.x, aB!.to.y - aB!.from.y)).toBeCloseTo(ARROW_MAX_PX, 9);
    expect(o.legend?.rows.map((r) => r.text)).toEqual(['= 20 length/s', '= 200 length/s²', 'dashed: clamped']);
    expect(o.legend?.rows[2].dashed).toBe(true);
  });
  it('gives the scale bar the length that the value would have as an arrow', () => {
    const s = arrowScale(20)!;
    expect(o.legend?.rows[0].barPx).toBeCloseTo(s.value * s.pxPerUnit, 12);
  });
  it('keeps the legend inside the canvas', () => {
    const b = o.legend!.box;
    expect(b.x).toBeGreaterThanOrEqual(0);
    expect(b.y).toBeGreaterThanOrEqual(0);
    expect(b.x + b.width).toBeLessThanOrEqual(640);
    expect(b.y + b.height).toBeLessThanOrEqual(420);
  });
  it('places the arrow labels so that no two labels overlap and none covers the legend', () => {
    const layout = layoutScene(scene, view, measureModel, o.exclusions, o.extras);
    const ids = layout.labels.map((l) => l.id);
    expect(ids).toEqual(expect.arrayContaining(['extra:vA', 'extra:vP', 'extra:aA', 'extra:aP', 'A', 'B', 'P']));
    const boxes = layout.labels.map((l) => l.box);
    const overlap = (a: (typeof boxes)[0], b: (typeof boxes)[0]) =>
      Math.max(0, Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x)) *
      Math.max(0, Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y));
    for (let i = 0; i < boxes.length; i++) {
      expect(overlap(boxes[i], o.legend!.box), ids[i]).toBe(0);
      for (let j = i + 1; j < boxes.length; j++) expect(overlap(boxes[i], boxes[j]), `${ids[i]} ${ids[j]}`).toBe(0);
    }
  });
  it('at a limit position draws only what is determined and says why', () => {
    const nan = { x: Number.NaN, y: Number.NaN };
    const limit: SceneVectors = { ...vectors, acceleration: null, velocity: { A: V.A, B: nan, P: nan }, limit: true };
    const lo = vectorOverlay(limit, scene.pose, view, measureModel);
    expect(lo.arrows.map((a) => `${a.kind}${a.at}`)).toEqual(['vA']);
    expect(lo.legend?.rows.at(-1)?.text).toBe('limit position');
  });
});

describe('drawLinkage with motion vectors', () => {
  it('keeps every label off the scale legend, on a small canvas all around the cycle', () => {
    let checked = 0;
    for (let deg = 0; deg < 360; deg += 15) {
      const vectors: SceneVectors = {
        velocity: V,
        acceleration: ACC,
        velocityScale: arrowScale(20),
        accelerationScale: arrowScale(200),
        limit: false,
        text: TEXT,
      };
      const scene = sceneWith(deg, vectors);
      const view = fitView(scene.bounds, 300, 200, { zoom: 1, panX: 0, panY: 0 });
      const ctx = new RecordingContext();
      const layout = drawLinkage(ctx as unknown as CanvasRenderingContext2D, scene, view);
      const legend = vectorOverlay(vectors, scene.pose, view, measureModel).legend!.box;
      for (const l of layout.labels) {
        const ox = Math.min(l.box.x + l.box.width, legend.x + legend.width) - Math.max(l.box.x, legend.x);
        const oy = Math.min(l.box.y + l.box.height, legend.y + legend.height) - Math.max(l.box.y, legend.y);
        expect(ox > 0 && oy > 0, `${l.id} at ${deg} deg`).toBe(false);
        checked++;
      }
    }
    expect(checked).toBeGreaterThan(100);
  });
});
