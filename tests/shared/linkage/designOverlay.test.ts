import { describe, expect, it } from 'vitest';
import type { SceneDesign } from '../../../src/shared/linkage/designOverlay';
import { clipLine, edgeMarker, layoutDesign, muOutsideBand } from '../../../src/shared/linkage/designOverlay';
import type { ScreenRect } from '../../../src/shared/canvas/rect';
import { layoutScene } from '../../../src/shared/linkage/sceneLayout';
import { THEME } from '../../../src/shared/canvas/canvasTheme';
import { fitView, toScreenX, toScreenY } from '../../../src/shared/canvas/view';
import { instantCenters } from '../../../src/solver/instantCenters';
import { designMetrics } from '../../../src/solver/metrics';
import { LINKAGES, measureModel, rad, sweepScenes } from './fixtures';

const RECT: ScreenRect = { x: 0, y: 0, width: 600, height: 400 };
const INSET = 14;

/** Independent check: is q on the segment from the inner rect's centre towards p (cross product ~ 0, same side)? */
function onRayTowards(q: { x: number; y: number }, p: { x: number; y: number }): boolean {
  const c = { x: 300, y: 200 };
  const cross = (q.x - c.x) * (p.y - c.y) - (q.y - c.y) * (p.x - c.x);
  const dot = (q.x - c.x) * (p.x - c.x) + (q.y - c.y) * (p.y - c.y);
  return Math.abs(cross) < 1e-6 * Math.hypot(p.x - c.x, p.y - c.y) * 400 && dot > 0;
}

describe('edgeMarker', () => {
  it('is null for a point on the canvas, inside the inset', () => {
    expect(edgeMarker({ x: 300, y: 200 }, RECT, INSET)).toBeNull();
    expect(edgeMarker({ x: INSET, y: 400 - INSET }, RECT, INSET)).toBeNull();
  });

  it('sits on the inset edge that the ray from the centre crosses, pointing at the point', () => {
    const cases = [
      { p: { x: 5000, y: 200 }, edge: 'right' },
      { p: { x: -5000, y: 210 }, edge: 'left' },
      { p: { x: 310, y: -1e9 }, edge: 'top' },
      { p: { x: 250, y: 900 }, edge: 'bottom' },
      { p: { x: 1e6, y: 1e6 }, edge: 'bottom' }, // 600 x 400: the diagonal leaves through the bottom first
      { p: { x: 1e12, y: -3e11 }, edge: 'right' },
    ] as const;
    for (const { p, edge } of cases) {
      const m = edgeMarker(p, RECT, INSET)!;
      expect(m, `${p.x}, ${p.y}`).not.toBeNull();
      const expected = { right: ['x', 600 - INSET], left: ['x', INSET], top: ['y', INSET], bottom: ['y', 400 - INSET] }[
        edge
      ] as ['x' | 'y', number];
      expect(m.at[expected[0]]).toBeCloseTo(expected[1], 9);
      expect(m.at.x).toBeGreaterThanOrEqual(INSET - 1e-9);
      expect(m.at.x).toBeLessThanOrEqual(600 - INSET + 1e-9);
      expect(m.at.y).toBeGreaterThanOrEqual(INSET - 1e-9);
      expect(m.at.y).toBeLessThanOrEqual(400 - INSET + 1e-9);
      expect(onRayTowards(m.at, p)).toBe(true);
      expect(Math.cos(m.dirRad) * (p.x - 300) + Math.sin(m.dirRad) * (p.y - 200)).toBeGreaterThan(0);
    }
  });

  it('gives no marker for a non-finite point', () => {
    expect(edgeMarker({ x: Infinity, y: 0 }, RECT, INSET)).toBeNull();
    expect(edgeMarker({ x: NaN, y: 0 }, RECT, INSET)).toBeNull();
  });
});

describe('clipLine', () => {
  it('keeps the part of a long line inside the rect, on the line', () => {
    const s = clipLine({ x: 100, y: 100 }, { x: 200, y: 150 }, RECT, 0, 1e9)!;
    expect(s[0]).toEqual({ x: 100, y: 100 });
    expect(s[1].x).toBeCloseTo(600, 9);
    expect(s[1].y).toBeCloseTo(350, 9);
    expect(clipLine({ x: -10, y: -10 }, { x: -20, y: -5 }, RECT, 0, 1)).toBeNull();
  });
});

function designFor(t: (typeof LINKAGES)[number], dc: boolean): SceneDesign {
  const m = designMetrics(t.linkage, 'open');
  return {
    muBandRad: { lo: rad(40), hi: rad(140) },
    deadCentres: dc && m.output ? [m.output.extended, m.output.folded] : null,
    swingText: 'swing 48.54°',
    instantCentres: null,
    offscreenText: (n, at) => (at ? `${n} (${at.x.toFixed(1)}, ${at.y.toFixed(1)})` : `${n} at ∞`),
  };
}

describe('layoutScene with the design overlay', () => {
  const report = LINKAGES[0];
  const scenes = sweepScenes(report, 'open', 'en', 15);

  it("draws the dead centres of the report's linkage where B is r4 from O4 and A, B are r2 + r3 / r3 - r2 apart", () => {
    const s = { ...scenes[3], design: designFor(report, true) };
    const v = fitView(s.bounds, 652, 368, { zoom: 1, panX: 0, panY: 0 });
    const lay = layoutScene(s, v, measureModel);
    expect(lay.design!.deadCentres).toHaveLength(2);
    const d = (a: { x: number; y: number }, b: { x: number; y: number }) => Math.hypot(a.x - b.x, a.y - b.y) / v.scale;
    const [ext, fold] = lay.design!.deadCentres;
    expect(d(ext.O2, ext.B)).toBeCloseTo(7, 9);
    expect(d(fold.O2, fold.B)).toBeCloseTo(3, 9);
    expect(d(ext.O4, ext.B)).toBeCloseTo(5, 9);
    expect(d(fold.O4, fold.B)).toBeCloseTo(5, 9);
    // The swing arc spans 48.537 degrees (independent: law of cosines at O4 of both triangles).
    const acos = (c: number) => Math.acos(c);
    const betaE = acos((36 + 25 - 49) / 60);
    const betaF = acos((36 + 25 - 9) / 60);
    const arc = lay.design!.swingArc!;
    expect(Math.abs(arc.toRad - arc.fromRad)).toBeCloseTo(Math.abs(betaE - betaF), 9);
    expect(lay.labels.some((l) => l.id === 'swing')).toBe(true);
  });

  it('places I13 and I24 labels without overlapping any other label, on and off the canvas', () => {
    let offscreen = 0;
    let onscreen = 0;
    for (const s0 of sweepScenes(report, 'open', 'en', 3)) {
      if (!s0.pose) continue;
      const ic = instantCenters(report.linkage, s0.theta2, s0.pose);
      const design = { ...designFor(report, true), instantCentres: ic };
      const s = { ...s0, design };
      const v = fitView(s.bounds, 652, 368, { zoom: 1, panX: 0, panY: 0 });
      const lay = layoutScene(s, v, measureModel);
      for (const c of lay.design!.centres) {
        const inside = c.p.x >= 14 && c.p.x <= 652 - 14 && c.p.y >= 14 && c.p.y <= 368 - 14;
        expect(c.edge === null).toBe(inside);
        if (c.edge) offscreen++;
        else onscreen++;
        expect(lay.dropped).not.toContain(c.name);
      }
      const boxes = lay.labels.map((l) => l.box);
      for (let i = 0; i < boxes.length; i++)
        for (let j = i + 1; j < boxes.length; j++) {
          const a = boxes[i];
          const b = boxes[j];
          const overlap = a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
          expect(overlap, `${lay.labels[i].id} / ${lay.labels[j].id}`).toBe(false);
        }
    }
    expect(offscreen).toBeGreaterThan(0);
    expect(onscreen).toBeGreaterThan(0);
  });

  it("draws each finite centre's construction lines through its own pins: I13 on O2A and O4B, I24 on AB and O2O4", () => {
    let checked = 0;
    for (const t of [LINKAGES[0], LINKAGES[1], LINKAGES[3]]) {
      for (const s0 of sweepScenes(t, 'open', 'en', 7)) {
        if (!s0.pose) continue;
        const ic = instantCenters(t.linkage, s0.theta2, s0.pose);
        if (ic.I13 === null || ic.I24 === null) continue;
        const s = { ...s0, design: { ...designFor(t, false), instantCentres: ic } };
        const v = fitView(s.bounds, 652, 368, { zoom: 0.5, panX: 0, panY: 0 });
        const lay = layoutScene(s, v, measureModel);
        // Independent pins: world coordinates from θ2 and the pose, projected by the view.
        const scr = (x: number, y: number) => ({ x: toScreenX(v, x), y: toScreenY(v, y) });
        const l = t.linkage;
        const O2 = scr(0, 0);
        const O4 = scr(l.r1, 0);
        const A = scr(l.r2 * Math.cos(s0.theta2), l.r2 * Math.sin(s0.theta2));
        const B = scr(
          l.r2 * Math.cos(s0.theta2) + l.r3 * Math.cos(s0.pose.theta3),
          l.r2 * Math.sin(s0.theta2) + l.r3 * Math.sin(s0.pose.theta3),
        );
        const pins = {
          I13: [
            [O2, A],
            [O4, B],
          ],
          I24: [
            [A, B],
            [O2, O4],
          ],
        } as const;
        // Distance of q from the line through a and b, in pixels.
        const off = (q: { x: number; y: number }, a: { x: number; y: number }, b: { x: number; y: number }) =>
          Math.abs((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x)) / Math.hypot(b.x - a.x, b.y - a.y);
        for (const c of lay.design!.centres) {
          const want = pins[c.name as 'I13' | 'I24'];
          expect(c.lines, c.name).toHaveLength(2);
          c.lines.forEach(([p, q], i) => {
            const [a, b2] = want[i];
            // Both ends on the line of this pair of pins (1e-6 px: rounding of the projection and the clip).
            const tol = 1e-6 * Math.max(1, Math.hypot(p.x, p.y), Math.hypot(q.x, q.y));
            expect(off(p, a, b2), `${c.name} line ${i} start`).toBeLessThan(tol);
            expect(off(q, a, b2), `${c.name} line ${i} end`).toBeLessThan(tol);
          });
        }
        checked++;
      }
    }
    expect(checked).toBeGreaterThan(20);
  });

  it('shows the centres of a parallelogram at infinity: lines parallel to their links, an arrow along them, a label', () => {
    const para = LINKAGES[2];
    let checked = 0;
    for (const s0 of sweepScenes(para, 'open', 'en', 20)) {
      if (!s0.pose) continue;
      const ic = instantCenters(para.linkage, s0.theta2, s0.pose);
      // Crank parallel to rocker and coupler parallel to ground (the open branch is a parallelogram up to its
      // change point at 180 degrees, an antiparallelogram after it): both centres at infinity.
      if (ic.I13 !== null || ic.I24 !== null) continue;
      const s = { ...s0, design: { ...designFor(para, false), instantCentres: ic } };
      const v = fitView(s.bounds, 652, 368, { zoom: 1, panX: 0, panY: 0 });
      const lay = layoutScene(s, v, measureModel);
      const centres = lay.design!.centres;
      expect(centres.map((c) => c.name)).toEqual(['I13', 'I24']);
      for (const c of centres) {
        expect(c.world).toBeNull();
        expect(c.edge).not.toBeNull();
        // Independent direction: I13 lies along the crank O2A, I24 along the coupler AB (screen y down).
        const A = { x: para.linkage.r2 * Math.cos(s0.theta2), y: para.linkage.r2 * Math.sin(s0.theta2) };
        const dir = c.name === 'I13' ? Math.atan2(-A.y, A.x) : Math.atan2(-(s0.pose.B.y - A.y), s0.pose.B.x - A.x);
        expect(Math.abs(Math.sin(c.edge!.dirRad - dir))).toBeLessThan(1e-9);
        expect(c.lines).toHaveLength(2);
        for (const [p, q] of c.lines)
          expect(Math.abs(Math.sin(Math.atan2(q.y - p.y, q.x - p.x) - dir))).toBeLessThan(1e-9);
        const label = lay.labels.find((l) => l.id === c.name);
        expect(label?.text).toBe(`${c.name} at ∞`);
        expect(lay.dropped).not.toContain(c.name);
      }
      checked++;
    }
    expect(checked).toBeGreaterThan(6);
  });

  it('turns the mu label to the warning colour exactly when mu leaves the band', () => {
    let seenOutside = 0;
    let seenInside = 0;
    for (const s0 of scenes) {
      if (!s0.pose) continue;
      // A band of 60 to 100 degrees: the report's mu runs 47.2 to 106.3, so both cases occur.
      const design = { ...designFor(report, false), muBandRad: { lo: rad(60), hi: rad(100) } };
      const v = fitView(s0.bounds, 652, 368, { zoom: 1, panX: 0, panY: 0 });
      const mu = layoutScene({ ...s0, design }, v, measureModel).labels.find((l) => l.id === 'mu');
      if (!mu) continue;
      const muDeg = (s0.pose.mu * 180) / Math.PI;
      const outside = muDeg < 60 || muDeg > 100;
      expect(mu.color).toBe(outside ? THEME.warning : THEME.angle);
      if (outside) seenOutside++;
      else seenInside++;
    }
    expect(seenOutside).toBeGreaterThan(0);
    expect(seenInside).toBeGreaterThan(0);
    expect(muOutsideBand(undefined, 0)).toBe(false);
  });
});

describe('layoutDesign', () => {
  it('draws nothing for a design with both parts hidden', () => {
    const s = sweepScenes(LINKAGES[0], 'open', 'en', 90)[0];
    const v = fitView(s.bounds, 600, 400, { zoom: 1, panX: 0, panY: 0 });
    const lay = layoutDesign(
      designFor(LINKAGES[0], false),
      s.linkage,
      v,
      {
        O2: { x: 0, y: 0 },
        O4: { x: 1, y: 0 },
        A: { x: 0, y: 1 },
        B: { x: 1, y: 1 },
      },
      RECT,
    );
    expect(lay).toEqual({ deadCentres: [], swingArc: null, centres: [] });
  });
});
