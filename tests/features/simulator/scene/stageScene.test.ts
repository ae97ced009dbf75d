import { describe, expect, it } from 'vitest';
import { createForceLayer } from '../../../../src/features/forces/forceLayer';
import { createStageScene } from '../../../../src/features/simulator/scene/stageScene';
import type { StageInputs } from '../../../../src/features/simulator/scene/stageScene';
import { computeCycle } from '../../../../src/features/simulator/solve/compute';
import { getMessages } from '../../../../src/shared/i18n/i18n';
import { sameBackground } from '../../../../src/shared/linkage/drawLinkage';
import type { AppState } from '../../../../src/shared/state/appState';
import { DEFAULT_STATE } from '../../../../src/shared/state/appState';
import type { PlayFrame } from '../../../../src/shared/state/playhead';
import type { Branch, Linkage } from '../../../../src/solver/types';
import { angleDiff, referenceSolve } from '../../../oracle/reference';
import { angleTolerance } from '../../../oracle/tolerance';

const t = getMessages('en');
const REPORT: Linkage = { r1: 6, r2: 2, r3: 5, r4: 5 };
const TRIPLE_ROCKER: Linkage = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
const sigma = (b: Branch) => (b === 'open' ? 1 : -1);

/** The default state with a linkage and display, motion and forces changes. */
function stateWith(
  linkage: Linkage,
  display: Partial<AppState['display']> = {},
  forces: Partial<AppState['forces']> = {},
  motion: Partial<AppState['motion']> = {},
): AppState {
  const s = DEFAULT_STATE;
  return {
    ...s,
    design: { ...s.design, linkage },
    display: { ...s.display, ...display },
    forces: { ...s.forces, ...forces },
    motion: { ...s.motion, ...motion },
  };
}

/** The inputs a page sends: the state, its cycle (both branches and the coupler curves) and the ghost shown. */
function inputsFor(state: AppState, ghostShown = true): StageInputs {
  const { linkage, branch, coupler } = state.design;
  const cycle = computeCycle({
    linkage,
    samples: 360,
    coupler: { distance: coupler.distance, angleRad: (coupler.angleDeg * Math.PI) / 180 },
    solver: { method: 'newton', tol: null },
    branch,
    otherBranch: true,
    curves: true,
  });
  return { state, cycle, ghostShown };
}

const frame = (theta2Deg: number, branch: Branch = 'open'): PlayFrame => ({ theta2Deg, direction: 1, branch });

describe('the live stage’s scene for a frame of Play', () => {
  it('poses the linkage as the oracle does, on the frame’s branch, with the other branch as the ghost', () => {
    let checked = 0;
    for (const l of [REPORT, TRIPLE_ROCKER]) {
      const build = createStageScene(createForceLayer());
      const inputs = inputsFor(stateWith(l));
      for (const branch of ['open', 'crossed'] as const) {
        for (let deg = 5; deg < 360; deg += 20) {
          const scene = build(inputs, frame(deg, branch), t);
          expect(scene.theta2).toBeCloseTo((deg * Math.PI) / 180, 14);
          const ref = referenceSolve(l, scene.theta2, sigma(branch));
          if (ref.kind !== 'unique') {
            if (ref.kind === 'unreachable') expect(scene.pose).toBeNull();
            continue;
          }
          if (!scene.pose || !scene.ghost) throw new Error(`no pose at ${deg}° on ${branch}`);
          const tol = angleTolerance(l, ref.pose);
          expect(Math.abs(angleDiff(scene.pose.theta3, ref.pose.theta3))).toBeLessThanOrEqual(tol.theta3);
          expect(Math.abs(angleDiff(scene.pose.theta4, ref.pose.theta4))).toBeLessThanOrEqual(tol.theta4);
          // B closes the loop: |AB| = r3 and |O4B| = r4.
          const { A, B } = scene.pose;
          expect(Math.hypot(B.x - A.x, B.y - A.y)).toBeCloseTo(l.r3, 9);
          expect(Math.hypot(B.x - l.r1, B.y)).toBeCloseTo(l.r4, 9);
          const other = referenceSolve(l, scene.theta2, -sigma(branch) as 1 | -1);
          if (other.kind === 'unique')
            expect(Math.abs(angleDiff(scene.ghost.theta4, other.pose.theta4))).toBeLessThanOrEqual(
              angleTolerance(l, other.pose).theta4,
            );
          checked++;
        }
      }
    }
    expect(checked).toBeGreaterThan(40);
  });

  it('draws only the overlays the state turns on: ghost, vectors, dead and instant centres, pin forces', () => {
    const plain = createStageScene(createForceLayer())(
      inputsFor(stateWith(REPORT, { showGhost: false })),
      frame(60),
      t,
    );
    expect(plain.ghost).toBeNull();
    expect(plain.vectors).toBeNull();
    expect(plain.forces).toBeUndefined();
    expect(plain.design?.deadCentres).toBeNull();
    expect(plain.design?.instantCentres).toBeNull();
    // Not shown because the canvas does not show it (the lab page), though the state's ghost is on.
    expect(createStageScene(createForceLayer())(inputsFor(stateWith(REPORT), false), frame(60), t).ghost).toBeNull();

    const omega = 3;
    const all = stateWith(
      REPORT,
      { showVelocity: true, showAcceleration: true, showDeadCentres: true, showInstantCentres: true },
      { enabled: true, showVectors: true },
      { omega2RadPerS: omega, alpha2RadPerS2: 0 },
    );
    const scene = createStageScene(createForceLayer())(inputsFor(all), frame(60), t);
    // The crank pin's speed is r2 ω2, at right angles to the crank.
    const vA = scene.vectors?.velocity?.A;
    if (!vA) throw new Error('no velocity at A');
    expect(Math.hypot(vA.x, vA.y)).toBeCloseTo(REPORT.r2 * omega, 10);
    const crank = { x: Math.cos(scene.theta2), y: Math.sin(scene.theta2) };
    expect(vA.x * crank.x + vA.y * crank.y).toBeCloseTo(0, 10);
    // Centripetal only (α2 = 0): r2 ω2² towards O2.
    const aA = scene.vectors?.acceleration?.A;
    if (!aA) throw new Error('no acceleration at A');
    expect(aA.x * crank.x + aA.y * crank.y).toBeCloseTo(-REPORT.r2 * omega * omega, 9);
    expect(scene.design?.deadCentres).toHaveLength(2);
    // Kennedy: I13 lies on the crank's line O2A and on the rocker's line O4B, at this frame's pose.
    const I13 = scene.design?.instantCentres?.I13;
    if (!I13 || !scene.pose) throw new Error('no I13');
    const { A, B } = scene.pose;
    const cross = (o: { x: number; y: number }, p: { x: number; y: number }, q: { x: number; y: number }) =>
      ((p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x)) /
      (Math.hypot(p.x - o.x, p.y - o.y) * Math.hypot(q.x - o.x, q.y - o.y));
    expect(Math.abs(cross({ x: 0, y: 0 }, A, I13))).toBeLessThan(1e-12);
    expect(Math.abs(cross({ x: REPORT.r1, y: 0 }, B, I13))).toBeLessThan(1e-12);
    expect(scene.forces?.pins).not.toBeNull();
  });

  it('keeps the background the same from frame to frame (its bitmap holds) until the inputs change', () => {
    const build = createStageScene(createForceLayer());
    const inputs = inputsFor(stateWith(REPORT));
    const a = build(inputs, frame(10), t);
    const b = build(inputs, frame(200), t);
    expect(sameBackground(a, b)).toBe(true);
    expect(a.bounds).toBe(b.bounds);
    const longer = inputsFor(stateWith({ ...REPORT, r1: 6.5 }));
    expect(sameBackground(b, build(longer, frame(200), t))).toBe(false);
  });

  it('fits the whole cycle: every joint of every frame lies within the scene’s bounds', () => {
    for (const l of [REPORT, TRIPLE_ROCKER]) {
      const build = createStageScene(createForceLayer());
      const inputs = inputsFor(stateWith(l));
      for (let deg = 0; deg < 360; deg += 3) {
        for (const branch of ['open', 'crossed'] as const) {
          const s = build(inputs, frame(deg, branch), t);
          if (!s.pose) continue;
          for (const p of [s.pose.A, s.pose.B, s.pose.P]) {
            expect(p.x).toBeGreaterThanOrEqual(s.bounds.minX - 1e-9);
            expect(p.x).toBeLessThanOrEqual(s.bounds.maxX + 1e-9);
            expect(p.y).toBeGreaterThanOrEqual(s.bounds.minY - 1e-9);
            expect(p.y).toBeLessThanOrEqual(s.bounds.maxY + 1e-9);
          }
        }
      }
    }
  });
});
