import { describe, expect, it } from 'vitest';
import { forceOverlay } from '../../../src/shared/linkage/forceVectors';
import type { ForceText, SceneForces } from '../../../src/shared/linkage/forceVectors';
import { ARROW_MAX_PX, ARROW_MIN_PX, arrowScale, vectorOverlay } from '../../../src/shared/linkage/motionVectors';
import type { SceneVectors } from '../../../src/shared/linkage/motionVectors';
import type { LinkageScene } from '../../../src/shared/linkage/scene';
import { drawLinkage } from '../../../src/shared/linkage/drawLinkage';
import { fitView } from '../../../src/shared/canvas/view';
import type { ScreenRect } from '../../../src/shared/canvas/rect';
import { RecordingContext, measureModel, reportScene } from './fixtures';

const TEXT: ForceText = {
  label: { O2: 'F12', A: 'F32', B: 'F43', O4: 'F14' },
  bar: (v) => `= ${v} N`,
  zero: 'F: zero',
  clamped: 'dashed: clamped',
  limit: 'limit position',
  formatValue: (x) => String(x),
};

/** Pin forces of every kind of length on screen: to scale, tiny (clamped short) and huge (clamped long). */
const PINS = { O2: { x: -300, y: 400 }, A: { x: 250, y: 0 }, B: { x: 0.01, y: 0 }, O4: { x: 0, y: -1e7 } };

function forcesWith(pins: SceneForces['pins'], limit = false): SceneForces {
  return { pins, scale: arrowScale(500), limit, text: TEXT };
}

/** The report's linkage at theta2 with the given forces (and motion vectors). */
function sceneWith(theta2Deg: number, forces: SceneForces, vectors: SceneVectors | null = null): LinkageScene {
  return reportScene(theta2Deg, { vectors, forces });
}

const overlap = (a: ScreenRect, b: ScreenRect) =>
  Math.max(0, Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x)) *
  Math.max(0, Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y));

describe('forceOverlay', () => {
  const forces = forcesWith(PINS);
  const scene = sceneWith(45, forces);
  const view = fitView(scene.bounds, 640, 420, { zoom: 1, panX: 0, panY: 0 });
  const o = forceOverlay(forces, scene.pose, view, measureModel);

  it('puts F12 at O2, F32 at A, F43 at B and F14 at O4, along the force on screen (y down)', () => {
    expect(o.arrows.map((a) => a.at)).toEqual(['O2', 'A', 'B', 'O4']);
    const f12 = o.arrows[0];
    expect(f12.from.x).toBeCloseTo(view.width / 2 + (0 - (scene.bounds.minX + scene.bounds.maxX) / 2) * view.scale, 6);
    const dx = f12.to.x - f12.from.x;
    const dy = f12.to.y - f12.from.y;
    // (-300, 400) with y flipped: parallel (cross product 0) and the same way (dot product > 0).
    expect(Math.abs(dx * -400 - dy * -300)).toBeLessThan(1e-9 * Math.hypot(dx, dy) * 500);
    expect(dx * -300 + dy * -400).toBeGreaterThan(0);
    // 500 N is the scale's typical force: drawn at 60 px.
    expect(Math.hypot(dx, dy)).toBeCloseTo(60, 9);
  });

  it('clamps the tiny and the huge force, dashes them and says so in the legend', () => {
    const [, , b, o4] = o.arrows;
    expect(b.clamped).toBe(true);
    expect(o4.clamped).toBe(true);
    expect(Math.hypot(b.to.x - b.from.x, b.to.y - b.from.y)).toBeCloseTo(ARROW_MIN_PX, 9);
    expect(Math.hypot(o4.to.x - o4.from.x, o4.to.y - o4.from.y)).toBeCloseTo(ARROW_MAX_PX, 9);
    expect(o.legend?.rows.map((r) => r.text)).toEqual(['= 500 N', 'dashed: clamped']);
  });

  it('labels the arrows through the label placement, off the legend and off each other', () => {
    const ctx = new RecordingContext();
    // A canvas with room for every label (a crowded one drops what finds no free spot, as for any label).
    const big = fitView(scene.bounds, 900, 600, { zoom: 1, panX: 0, panY: 0 });
    const layout = drawLinkage(ctx as unknown as CanvasRenderingContext2D, scene, big);
    const legend = forceOverlay(forces, scene.pose, big, measureModel).legend!.box;
    const ids = layout.labels.map((l) => l.id);
    expect(ids).toEqual(expect.arrayContaining(['extra:FO2', 'extra:FA', 'extra:FB', 'extra:FO4']));
    const boxes = layout.labels.map((l) => l.box);
    for (let i = 0; i < boxes.length; i++) {
      expect(overlap(boxes[i], legend), ids[i]).toBe(0);
      for (let j = i + 1; j < boxes.length; j++) expect(overlap(boxes[i], boxes[j]), `${ids[i]} ${ids[j]}`).toBe(0);
    }
  });

  it('stacks its legend above the motion vectors’ legend, both inside the canvas', () => {
    const vectors: SceneVectors = {
      velocity: { A: { x: 1, y: 1 }, B: { x: 1, y: 0 }, P: { x: 0, y: 1 } },
      acceleration: null,
      velocityScale: arrowScale(1),
      accelerationScale: null,
      limit: false,
      text: {
        symbol: { v: 'v', a: 'a' },
        velocityBar: (v) => `= ${v} m/s`,
        accelerationBar: (v) => `= ${v} m/s²`,
        zero: 'zero',
        clamped: 'dashed',
        limit: 'limit',
        formatValue: String,
      },
    };
    const motion = vectorOverlay(vectors, scene.pose, view, measureModel).legend!.box;
    const above = forceOverlay(forces, scene.pose, view, measureModel, motion).legend!.box;
    expect(overlap(above, motion)).toBe(0);
    expect(above.y + above.height).toBeLessThanOrEqual(motion.y);
    expect(above.y).toBeGreaterThanOrEqual(0);
    expect(above.x + above.width).toBeLessThanOrEqual(view.width);
  });

  it('at a limit position draws no arrow and says why; zero forces get no arrow and the zero row', () => {
    const limit = forceOverlay(forcesWith(null, true), scene.pose, view, measureModel);
    expect(limit.arrows).toEqual([]);
    expect(limit.legend?.rows.map((r) => r.text)).toEqual(['= 500 N', 'limit position']);
    const zero = { x: 0, y: 0 };
    const none = forceOverlay(
      { pins: { O2: zero, A: zero, B: zero, O4: zero }, scale: null, limit: false, text: TEXT },
      scene.pose,
      view,
      measureModel,
    );
    expect(none.arrows).toEqual([]);
    expect(none.legend?.rows.map((r) => r.text)).toEqual(['F: zero']);
  });
});
