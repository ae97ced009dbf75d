import { describe, expect, it } from 'vitest';
import { crankAngleAt, couplerAt } from '../../../src/shared/canvas/canvasGestures';
import { placementTransform, toScreenX, toScreenY } from '../../../src/shared/canvas/view';
import { fitScene } from '../../../src/shared/linkage/scene';
import { layoutScene } from '../../../src/shared/linkage/sceneLayout';
import { LINKAGES, measureModel, sweepScenes } from './fixtures';

const OFFSET = { zoom: 1, panX: 0, panY: 0 };
const W = 652;
const H = 368;

describe('a placed scene (URL ox, oy, og)', () => {
  const report = LINKAGES[0];
  const scenes = sweepScenes(report, 'open', 'en', 15);
  const g = (35 * Math.PI) / 180;
  const O = { x: 12, y: -4 };
  const placement = placementTransform(O.x, O.y, g)!;

  it('is the unplaced scene without a placement or markers', () => {
    const s = scenes[3];
    expect(fitScene(s, s.bounds, W, H, OFFSET)).toEqual(fitScene({}, s.bounds, W, H, OFFSET));
    expect(fitScene(s, s.bounds, W, H, OFFSET).frame).toBeUndefined();
  });

  it('draws O2 at the placement and every joint turned by the ground angle (a rigid transform)', () => {
    const s = { ...scenes[3], placement };
    const v = fitScene(s, s.bounds, W, H, OFFSET);
    const lay = layoutScene(s, v, measureModel);
    // Independent of the code's frame helpers: rotate by g, translate by O, then to screen.
    const world = (p: { x: number; y: number }) => ({
      x: O.x + Math.cos(g) * p.x - Math.sin(g) * p.y,
      y: O.y + Math.sin(g) * p.x + Math.cos(g) * p.y,
    });
    const screen = (p: { x: number; y: number }) => ({ x: toScreenX(v, world(p).x), y: toScreenY(v, world(p).y) });
    const pose = s.pose!;
    for (const [name, p] of [
      ['O2', { x: 0, y: 0 }],
      ['O4', { x: report.linkage.r1, y: 0 }],
      ['A', pose.A],
      ['B', pose.B],
      ['P', pose.P],
    ] as const) {
      const drawn = lay.joints[name]!;
      // Pixels of a few hundred: 1e-9 px is rounding.
      expect(drawn.x, name).toBeCloseTo(screen(p).x, 9);
      expect(drawn.y, name).toBeCloseTo(screen(p).y, 9);
    }
    // The θ2 arc starts on the ground line, which now points at g.
    const arc = lay.arcs.find((a) => a.centre === lay.joints.O2);
    expect(arc?.fromRad).toBeCloseTo(g, 12);
  });

  it('labels the angles from the ground line, as the unplaced scene does', () => {
    const s = scenes[3];
    const plain = layoutScene(s, fitScene(s, s.bounds, W, H, OFFSET), measureModel);
    const placed = { ...s, placement };
    const turned = layoutScene(placed, fitScene(placed, placed.bounds, W, H, OFFSET), measureModel);
    const texts = (l: typeof plain) =>
      l.labels
        .map((x) => x.text)
        .filter((x) => /^θ|^μ/.test(x))
        .sort();
    expect(texts(turned)).toEqual(texts(plain));
  });

  it('turns a drag of A or P back into the linkage’s own angles', () => {
    const s = { ...scenes[3], placement };
    const v = fitScene(s, s.bounds, W, H, OFFSET);
    const lay = layoutScene(s, v, measureModel);
    expect(crankAngleAt(v, lay.joints.A)).toBeCloseTo((s.theta2 * 180) / Math.PI, 1);
    const c = couplerAt(s, v, lay.joints.P!);
    expect(c?.distance).toBeCloseTo(report.coupler.distance, 2);
    expect(c?.angleDeg).toBeCloseTo(report.coupler.angleDeg, 1);
  });

  it('fits the markers into the view', () => {
    const s = { ...scenes[3], markers: [{ x: 40, y: 30 }] };
    const v = fitScene(s, s.bounds, W, H, OFFSET);
    const x = toScreenX(v, 40);
    const y = toScreenY(v, 30);
    expect(x).toBeGreaterThanOrEqual(0);
    expect(x).toBeLessThanOrEqual(W);
    expect(y).toBeGreaterThanOrEqual(0);
    expect(y).toBeLessThanOrEqual(H);
  });
});
