import { describe, expect, it } from 'vitest';
import type { MotionPicture } from '../../../../src/features/synthesis/motion/motionPicture';
import {
  drawMotion,
  motionBounds,
  pointLabelPlacements,
} from '../../../../src/features/synthesis/motion/motionPicture';
import { solveMotion, toPose } from '../../../../src/features/synthesis/motion/motionSolve';
import { DEFAULT_POSES_FIVE, DEFAULT_SYN_MOTION } from '../../../../src/shared/state/slices/synMotionSlice';
import type { Bounds } from '../../../../src/shared/canvas/view';
import { fitView } from '../../../../src/shared/canvas/view';
import type { DrawContext } from '../../../../src/shared/canvas/drawContext';
import type { Point } from '../../../../src/solver';
import { burmesterCurves, burmesterPoints, placedJoints, toPlane } from '../../../../src/synthesis';
import { segmentHitsBox } from '../../../../src/shared/canvas/rect';
import { toScreenX, toScreenY } from '../../../../src/shared/canvas/view';
import { RecordingContext } from '../../../shared/linkage/fixtures';

function pictureOf(count: 4 | 5): MotionPicture {
  const s = { ...DEFAULT_SYN_MOTION, poses: DEFAULT_POSES_FIVE.slice(0, count) };
  return {
    poses: s.poses.map(toPose),
    selected: 0,
    outcome: solveMotion(s),
    pivotChoice: s.pivotChoice,
    pivots: s.pivots,
    shownPose: 0,
    cursor: null,
    legend: { centre: 'centre-point curve', circle: 'circle-point curve' },
  };
}

const inside = (b: Bounds, p: Point) => p.x >= b.minX && p.x <= b.maxX && p.y >= b.minY && p.y <= b.maxY;
const dist = (a: Point, b: Point) => Math.hypot(a.x - b.x, a.y - b.y);

describe('motionBounds (issue 34, item 8)', () => {
  it('four poses: the fit holds a stretch of each curve, from its point nearest the poses on', () => {
    const pic = pictureOf(4);
    const b = motionBounds(pic);
    // The curves computed here, with their own sampling, not the page's: the nearest centre point is 8 units and the
    // nearest circle point 5.8 units from the poses, which span 4.5 by 1.9 (off the old view).
    const curves = burmesterCurves(pic.poses, { samples: 200 });
    const c = { x: -3.025, y: 0.525 };
    for (const points of [
      curves.flat().map((d) => d.center),
      curves.flat().map((d) => toPlane(pic.poses[0], d.circle)),
    ]) {
      const nearest = Math.min(...points.map((p) => dist(p, c)));
      expect(nearest).toBeGreaterThan(5);
      // The points at most 1.5 times as far as the nearest: a stretch of the curve, not one dot.
      const near = points.filter((p) => dist(p, c) <= 1.5 * nearest);
      expect(near.length).toBeGreaterThan(10);
      for (const p of near) expect(inside(b, p)).toBe(true);
    }
    // Not the asymptotic arms: the box stays within a few times the nearest curve's distance.
    expect(Math.max(b.maxX - b.minX, b.maxY - b.minY)).toBeLessThan(50);
  });

  it('five poses: the fit holds every Burmester point and circle point but a far one (540 units away)', () => {
    const pic = pictureOf(5);
    const b = motionBounds(pic);
    const points = burmesterPoints(pic.poses);
    expect(points).toHaveLength(4);
    const c = { x: -3.64, y: -0.04 };
    let far = 0;
    for (const d of points) {
      for (const p of [d.center, toPlane(pic.poses[0], d.circle)]) {
        if (dist(p, c) > 100) far++;
        else expect(inside(b, p)).toBe(true);
      }
    }
    expect(far).toBe(1);
    expect(Math.max(b.maxX - b.minX, b.maxY - b.minY)).toBeLessThan(100);
  });
});

describe('drawMotion', () => {
  it('numbers the Burmester points as the four-bar list names them, 1 to 4, at each point', () => {
    const pic = pictureOf(5);
    if (pic.outcome.count !== 5) throw new Error('five poses');
    const ctx = new RecordingContext();
    const v = fitView(motionBounds(pic), 800, 500, { zoom: 1, panX: 0, panY: 0 });
    drawMotion(ctx as unknown as DrawContext, pic, v);
    const texts = ctx.calls.filter((k) => k.op === 'fillText').map((k) => k.text);
    // Each number twice (centre point and circle point) where the point is in view; pose numbers 1 to 5 once each.
    const onCanvas = (p: Point) => {
      const x = toScreenX(v, p.x);
      const y = toScreenY(v, p.y);
      return x >= 0 && x <= 800 && y >= 0 && y <= 500;
    };
    const o = pic.outcome;
    ['1', '2', '3', '4'].forEach((n, i) => {
      const d = o.points[i];
      const shown = [d.center, toPlane(pic.poses[0], d.circle)].filter(onCanvas).length;
      expect(texts.filter((t) => t === n)).toHaveLength(1 + shown);
    });
    expect(texts.filter((t) => t === '5')).toHaveLength(1);
  });

  it('numbers the Burmester points over the linkage, not under it (issue 34)', () => {
    const pic = pictureOf(5);
    if (pic.outcome.count !== 5 || !pic.outcome.chosen) throw new Error('five poses, a four-bar');
    const ctx = new RecordingContext();
    const v = fitView(motionBounds(pic), 800, 500, { zoom: 1, panX: 0, panY: 0 });
    drawMotion(ctx as unknown as DrawContext, pic, v);
    // The pose numbers are drawn after the linkage; every Burmester number comes after all of them.
    const texts = ctx.calls.map((k, i) => ({ ...k, i })).filter((k) => k.op === 'fillText');
    const lastPose = texts.filter((k) => k.text === '5')[0].i;
    const points = texts.filter((k) => k.i > lastPose);
    // Every number (but those of a point out of view: the far one, 540 units away) and none before.
    expect(points.length).toBeGreaterThanOrEqual(2 * pic.outcome.points.length - 2);
    expect(texts.filter((k) => k.i < lastPose && /^[1-4]$/.test(k.text ?? '')).length).toBe(4);
  });

  for (const [w, h] of [
    [800, 500],
    [360, 300],
  ] as const) {
    it(`places the Burmester numbers off the linkage shown and apart, at ${w}×${h}`, () => {
      const pic = pictureOf(5);
      if (pic.outcome.count !== 5 || !pic.outcome.chosen) throw new Error('five poses, a four-bar');
      const ctx = new RecordingContext();
      const v = fitView(motionBounds(pic), w, h, { zoom: 1, panX: 0, panY: 0 });
      const { placements } = pointLabelPlacements(ctx as unknown as DrawContext, pic, v);
      expect(placements.length).toBeGreaterThanOrEqual(6);
      // The linkage drawn solid, in screen pixels, computed here from the design (not the placer's obstacles).
      const c = pic.outcome.chosen;
      const j = placedJoints(c.design, c.theta2[0])!;
      const s = (p: Point) => ({ x: toScreenX(v, p.x), y: toScreenY(v, p.y) });
      const links = [
        [j.O2, j.A],
        [j.A, j.B],
        [j.B, j.O4],
        [j.A, j.P],
        [j.B, j.P],
      ].map(([a, b]) => [s(a), s(b)] as const);
      for (const l of placements) {
        for (const [a, b] of links) {
          // The link's line widened by 3 px each side: the box grown by 3 px.
          const { x, y, width, height } = l.box;
          expect(segmentHitsBox(a.x, a.y, b.x, b.y, x - 3, y - 3, x + width + 3, y + height + 3), l.id).toBe(false);
        }
        for (const q of [j.O2, j.A, j.B, j.O4, j.P].map(s)) {
          const inside =
            q.x > l.box.x - 5 &&
            q.x < l.box.x + l.box.width + 5 &&
            q.y > l.box.y - 5 &&
            q.y < l.box.y + l.box.height + 5;
          expect(inside, l.id).toBe(false);
        }
        for (const o of placements) {
          if (o === l) continue;
          const overlap =
            l.box.x < o.box.x + o.box.width &&
            o.box.x < l.box.x + l.box.width &&
            l.box.y < o.box.y + o.box.height &&
            o.box.y < l.box.y + l.box.height;
          expect(overlap, `${l.id} ${o.id}`).toBe(false);
        }
      }
    });
  }
});
