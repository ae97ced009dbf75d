import { describe, expect, it, vi } from 'vitest';
import { createFramePoser } from '../../../src/features/simulator/framePoser';
import { createFramePoseSource, derivedSource } from '../../../src/shared/linkage/FramePoseContext';
import type { AppState } from '../../../src/shared/state/appState';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import type { PlayFrame } from '../../../src/shared/state/playhead';
import type { Branch, Linkage } from '../../../src/solver/types';
import { angleDiff, referenceSolve } from '../../oracle/reference';
import { angleTolerance } from '../../oracle/tolerance';

const REPORT: Linkage = { r1: 6, r2: 2, r3: 5, r4: 5 };
const sigma = (b: Branch) => (b === 'open' ? 1 : -1);

function stateWith(linkage: Linkage, theta2Deg = 30, branch: Branch = 'open'): AppState {
  const s = DEFAULT_STATE;
  return { ...s, design: { ...s.design, linkage, branch }, motion: { ...s.motion, theta2Deg } };
}

const frame = (theta2Deg: number, branch: Branch = 'open'): PlayFrame => ({ theta2Deg, direction: 1, branch });

describe('createFramePoser', () => {
  it("poses Play's frame ahead of the state, against a 60-digit solve", () => {
    const poser = createFramePoser();
    const state = stateWith(REPORT, 30);
    for (const branch of ['open', 'crossed'] as const) {
      for (let deg = 7; deg < 360; deg += 31) {
        const f = poser(state, frame(deg, branch), false);
        expect(f.committed).toBe(state);
        expect(f.state.motion.theta2Deg).toBe(deg);
        expect(f.state.design.branch).toBe(branch);
        const ref = referenceSolve(REPORT, (deg * Math.PI) / 180, sigma(branch));
        if (ref.kind !== 'unique') throw new Error(`the report's linkage assembles at ${deg}°`);
        const pose = f.local.pose;
        if (!pose) throw new Error(`no pose at ${deg}°`);
        const tol = angleTolerance(REPORT, ref.pose);
        expect(Math.abs(angleDiff(pose.theta3, ref.pose.theta3))).toBeLessThanOrEqual(tol.theta3);
        expect(Math.abs(angleDiff(pose.theta4, ref.pose.theta4))).toBeLessThanOrEqual(tol.theta4);
        expect(f.marker.pose).toBe(pose);
        expect(f.motion?.rates).toBeDefined();
      }
    }
  });

  it("is the state's own frame when no frame plays", () => {
    const state = stateWith(REPORT, 75);
    const f = createFramePoser()(state, null, false);
    expect(f.state).toBe(state);
    expect(f.local.theta2Rad).toBeCloseTo((75 * Math.PI) / 180, 15);
  });

  it('gives the same object for the same state, the same frame by value and the same ghost', () => {
    const poser = createFramePoser();
    const state = stateWith(REPORT);
    const a = poser(state, frame(40), true);
    expect(poser(state, frame(40), true)).toBe(a);
    expect(poser(state, frame(41), true)).not.toBe(a);
    expect(poser(state, frame(41), false)).not.toBe(poser(state, frame(41), true));
  });

  it('keeps the pose, its point and its rates for a new state whose pose inputs are the same', () => {
    const poser = createFramePoser();
    const state = stateWith(REPORT);
    const a = poser(state, frame(50), false);
    const panned: AppState = { ...state, display: { ...state.display, view: { zoom: 2, panX: 3, panY: -1 } } };
    const b = poser(panned, frame(50), false);
    expect(b).not.toBe(a);
    expect(b.committed).toBe(panned);
    expect(b.local).toBe(a.local);
    expect(b.marker).toBe(a.marker);
    expect(b.motion).toBe(a.motion);
    const faster = { ...state, motion: { ...state.motion, omega2RadPerS: state.motion.omega2RadPerS * 2 } };
    const c = poser(faster, frame(50), false);
    expect(c.local).toBe(a.local);
    expect(c.motion).not.toBe(a.motion);
    expect(c.motion?.rates.omega3).toBeCloseTo(2 * (a.motion?.rates.omega3 ?? Number.NaN), 12);
    const longer = stateWith({ ...REPORT, r3: 5.5 });
    expect(poser(longer, frame(50), false).local).not.toBe(a.local);
  });
});

describe('derivedSource', () => {
  it('derives once per frame and tells its readers at each new frame', () => {
    const poser = createFramePoser();
    const state = stateWith(REPORT);
    const source = createFramePoseSource(poser(state, frame(10), false));
    const derive = vi.fn((f: ReturnType<typeof poser>) => f.state.motion.theta2Deg);
    const theta = derivedSource(source, derive);
    const heard = vi.fn();
    const stop = theta.subscribe(heard);
    expect(theta.get()).toBe(10);
    expect(theta.get()).toBe(10);
    expect(derive).toHaveBeenCalledTimes(1);
    source.set(poser(state, frame(20), false));
    source.notify();
    expect(heard).toHaveBeenCalledTimes(1);
    expect(theta.get()).toBe(20);
    expect(derive).toHaveBeenCalledTimes(2);
    stop();
    source.set(poser(state, frame(30), false));
    source.notify();
    expect(heard).toHaveBeenCalledTimes(1);
  });
});
