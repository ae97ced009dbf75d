import { describe, expect, it } from 'vitest';
import { ViewGestures, wheelZoom } from '../../../src/features/spatial/viewGestures';

describe('ViewGestures', () => {
  it('turns the view a full turn for a drag over its height (right: azimuth up; down: elevation up)', () => {
    const g = new ViewGestures();
    g.down({ id: 1, x: 100, y: 100, pans: false });
    const [m] = g.move(1, 100 + 400, 100, 400);
    expect(m).toEqual({ op: 'orbit', dAzimuth: 2 * Math.PI, dElevation: 0 });
    const [n] = g.move(1, 500, 100 + 100, 400);
    expect(n).toEqual({ op: 'orbit', dAzimuth: 0, dElevation: Math.PI / 2 });
    g.up(1);
    expect(g.move(1, 0, 0, 400)).toEqual([]);
  });

  it('pans with a modified drag so the scene follows the pointer (screen y down is view y up)', () => {
    const g = new ViewGestures();
    g.down({ id: 7, x: 0, y: 0, pans: true });
    expect(g.move(7, 50, 20, 200)).toEqual([{ op: 'pan', dx: 0.25, dy: -0.1 }]);
  });

  it('pinches to zoom by the ratio of the fingers’ distances and pans by their midpoint', () => {
    const g = new ViewGestures();
    g.down({ id: 1, x: 100, y: 100, pans: false });
    g.down({ id: 2, x: 200, y: 100, pans: false });
    // Finger 2 moves out by 100 px: distance 100 -> 200 (zoom 2), midpoint 150 -> 200 (pan 50 px of a 500 px view).
    expect(g.move(2, 300, 100, 500)).toEqual([
      { op: 'zoom', factor: 2 },
      { op: 'pan', dx: 0.1, dy: -0 },
    ]);
  });

  it('zooms by 1.2 per 100 px of wheel, closer for a wheel up', () => {
    expect(wheelZoom(-100)).toEqual({ op: 'zoom', factor: 1.2 });
    const out = wheelZoom(200);
    expect(out.op === 'zoom' && out.factor).toBeCloseTo(1 / 1.44, 12);
  });
});
