import { describe, expect, it } from 'vitest';
import { SvgContext } from '../../../src/shared/canvas/svgContext';
import { drawGroundTriangle, drawJoint, drawLink } from '../../../src/shared/linkage/linkPrimitives';

/** The numbers of each drawn path's d attribute (SvgContext writes M x y, L x y, A …, Z), in drawing order. */
function paths(draw: (ctx: SvgContext) => void): number[][] {
  const ctx = new SvgContext(100, 100);
  draw(ctx);
  return [...ctx.toSvg().matchAll(/<path[^>]*\sd="([^"]*)"/g)].map((m) =>
    m[1]
      .replace(/[MLAZ]/g, ' ')
      .trim()
      .split(/\s+/)
      .filter((s) => s !== '')
      .map(Number),
  );
}

describe('linkPrimitives', () => {
  it('draws a link from one end to the other', () => {
    const [d] = paths((ctx) => drawLink(ctx, { x: 10, y: 20 }, { x: 70, y: 45 }, '#123456', 4));
    expect(d).toEqual([10, 20, 70, 45]);
  });

  it('draws the pivot triangle with its apex at the pivot and its base 1.5 s below, 2 s wide', () => {
    const [d] = paths((ctx) => drawGroundTriangle(ctx, { x: 50, y: 30 }, 10));
    expect(d).toEqual([50, 30, 40, 45, 60, 45]);
  });

  it('draws a joint as a circle of radius r about its centre', () => {
    const [d] = paths((ctx) => drawJoint(ctx, { x: 50, y: 50 }, 5));
    // Every point the circle's arcs pass through lies r from the centre.
    const xy = d.length >= 2 ? [d[0], d[1], d[d.length - 2], d[d.length - 1]] : [];
    for (let i = 0; i < xy.length; i += 2) expect(Math.hypot(xy[i] - 50, xy[i + 1] - 50)).toBeCloseTo(5, 3);
    expect(xy.length).toBe(4);
  });
});
