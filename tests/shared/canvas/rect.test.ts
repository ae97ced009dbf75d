import { describe, expect, it } from 'vitest';
import { halfExtentAlong, segmentHitsBox } from '../../../src/shared/canvas/rect';

/** Park-Miller generator: a reproducible stream in [0, 1). */
function seeded(seed: number): () => number {
  let s = seed;
  return () => {
    s = (s * 48271) % 2147483647;
    return s / 2147483647;
  };
}

describe('segmentHitsBox', () => {
  it('agrees with dense sampling of the segment on 2000 random segments and boxes', () => {
    const rnd = seeded(11);
    let hits = 0;
    for (let n = 0; n < 2000; n++) {
      const [ax, ay, bx, by] = [rnd() * 100, rnd() * 100, rnd() * 100, rnd() * 100];
      const x0 = rnd() * 80;
      const y0 = rnd() * 80;
      const x1 = x0 + 1 + rnd() * 30;
      const y1 = y0 + 1 + rnd() * 30;
      // Oracle: some of 20 001 points along the segment lies strictly inside the box, 0.01 px in from each edge
      // (the margin keeps grazing segments, where sampling and clipping may differ, out of the comparison).
      let inside = false;
      let near = false;
      for (let i = 0; i <= 20000; i++) {
        const x = ax + ((bx - ax) * i) / 20000;
        const y = ay + ((by - ay) * i) / 20000;
        if (x > x0 + 0.01 && x < x1 - 0.01 && y > y0 + 0.01 && y < y1 - 0.01) inside = true;
        else if (x > x0 - 0.01 && x < x1 + 0.01 && y > y0 - 0.01 && y < y1 + 0.01) near = true;
      }
      if (!inside && near) continue;
      expect(segmentHitsBox(ax, ay, bx, by, x0, y0, x1, y1)).toBe(inside);
      if (inside) hits++;
    }
    expect(hits).toBeGreaterThan(200);
  });

  it('handles vertical and horizontal segments and a segment that ends inside', () => {
    expect(segmentHitsBox(5, -10, 5, 10, 0, 0, 10, 10)).toBe(true);
    expect(segmentHitsBox(-5, 5, 15, 5, 0, 0, 10, 10)).toBe(true);
    expect(segmentHitsBox(10, -10, 10, 20, 0, 0, 10, 10)).toBe(false);
    expect(segmentHitsBox(-5, -5, 3, 3, 0, 0, 10, 10)).toBe(true);
    expect(segmentHitsBox(-5, -5, -1, 20, 0, 0, 10, 10)).toBe(false);
  });
});

describe('halfExtentAlong', () => {
  it('is half the width sideways, half the height upright, and the corner distance on the diagonal', () => {
    expect(halfExtentAlong(1, 0, 40, 10)).toBe(20);
    expect(halfExtentAlong(0, -1, 40, 10)).toBe(5);
    const u = Math.SQRT1_2;
    expect(halfExtentAlong(u, u, 10, 10)).toBeCloseTo(Math.hypot(5, 5), 12);
  });
});
