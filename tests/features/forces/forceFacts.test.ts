import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import type { AppState } from '../../../src/shared/state/appState';
import { localPose } from '../../../src/shared/linkage/localPose';
import { forcesMessagesEn as t } from '../../../src/features/forces/forcesMessagesEn';
import { forcesMessagesZhTw as zh } from '../../../src/features/forces/forcesMessagesZhTw';
import {
  MISSING,
  cycleFacts,
  poseFacts,
  poseReason,
  shownMean,
  toggleNote,
} from '../../../src/features/forces/forceFacts';
import { forceSetup, poseForces } from '../../../src/features/forces/forceModel';
import { cycleForces } from '../../../src/features/forces/forceCycleData';
import { createForceLayer } from '../../../src/features/forces/forceLayer';

const ON: AppState = { ...DEFAULT_STATE, forces: { ...DEFAULT_STATE.forces, enabled: true } };

describe('poseFacts', () => {
  it('reads "Input torque T12" then its value in N·m, and each pin force as magnitude and direction', () => {
    const setup = forceSetup(ON);
    const local = localPose(ON.design.linkage, 45, 'open', ON.design.coupler, false);
    const p = poseForces(setup, local.theta2Rad, local.pose);
    const facts = poseFacts(p, t);
    expect(facts[0].label).toBe('Input torque T12');
    expect(facts[0].value).toMatch(/^−?\d[\d.]* N·m$/);
    expect(Number(facts[0].value.replace('−', '-').split(' ')[0])).toBeCloseTo(p.forces!.torque, 3);
    expect(facts.find((f) => f.key === 'F12')?.value).toMatch(/^\d[\d.]* N, at \d+(\.\d)?°$/);
    expect(poseReason(p, t)).toBeNull();
  });

  it('shows a pin force or moment that is rounding noise beside the others as 0, without a direction', () => {
    const P = (x: number, y: number) => ({ x, y });
    const facts = poseFacts(
      {
        status: 'ok',
        sinMu: 1,
        forces: {
          status: 'ok',
          torque: 40,
          F12: P(100, 0),
          F32: P(1e-17, -1e-17),
          F43: P(0, -50),
          F14: P(-3, 4),
          shakingForce: P(2e-15, 0),
          shakingMoment: -4e-14,
        },
      },
      t,
    );
    const value = (k: string) => facts.find((f) => f.key === k)?.value;
    expect(value('F32')).toBe('0 N');
    expect(value('shakingForce')).toBe('0 N');
    expect(value('shakingMoment')).toBe('0 N·m');
    expect(value('F14')).toMatch(/^5 N, at 126\.9°$/);
    expect(value('torque')).toBe('40 N·m');
  });

  it('shows "—" with the reason at a limit position, never NaN', () => {
    const p = poseForces(forceSetup(ON), 0.3, { theta3: 1, theta4: 1 });
    const facts = poseFacts(p, t);
    for (const f of facts) expect(f.value).toBe(MISSING);
    expect(poseReason(p, t)).toBe(t.limitReason);
    expect(JSON.stringify(facts)).not.toMatch(/NaN|Infinity/);
  });

  it('says the pin forces grow like 1/sin μ near a toggle, and nothing away from one', () => {
    const setup = forceSetup(ON);
    const near = poseForces(setup, 0.3, { theta3: 1, theta4: 1.1 });
    expect(toggleNote(near, 0.1, t)).toMatch(/1\/sin μ, here 10 times/);
    const far = poseForces(setup, 0.3, { theta3: 0, theta4: 1.5 });
    expect(toggleNote(far, 1.5, t)).toBeNull();
  });
});

describe('cycleFacts', () => {
  it('gives ΔE and the flywheel for k, and shows a zero mean as 0', () => {
    const c = cycleForces(forceSetup(ON), 'open', 360);
    const f = cycleFacts(c, 10, t);
    expect(f.reason).toBeNull();
    expect(f.energy).toMatch(/ J$/);
    expect(f.flywheel).toMatch(/ kg·m²$/);
    // Bars under gravity at a steady speed: the motor only lends energy and takes it back.
    expect(f.mean).toBe('0 N·m');
    expect(shownMean({ mean: 1e-3, peak: 10 })).toBe(1e-3);
  });

  it('says why there is no cycle for a crank that cannot turn, and for a crank at rest', () => {
    const rocker: AppState = { ...ON, design: { ...ON.design, linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 } } };
    const f = cycleFacts(cycleForces(forceSetup(rocker), 'open', 90), 10, t);
    expect(f.reason).toBe(t.cycleGaps['crank-does-not-turn']);
    expect([f.mean, f.energy, f.flywheel]).toEqual([MISSING, MISSING, MISSING]);
    const atRest = { ...ON, motion: { ...ON.motion, omega2RadPerS: 0 } };
    const still = cycleFacts(cycleForces(forceSetup(atRest), 'open', 90), 0, t);
    expect(still.reason).toBe(t.cycleGaps['omega-zero']);
    // A crank at rest has a torque over the turn (gravity) but no speed to steady: the flywheel is "—", not NaN.
    expect(still.energy).toMatch(/ J$/);
    expect(still.flywheel).toBe(MISSING);
    expect(JSON.stringify(still)).not.toMatch(/NaN|Infinity/);
  });
});

describe('createForceLayer', () => {
  const local = localPose(ON.design.linkage, 45, 'open', ON.design.coupler, false);

  it('solves nothing and draws nothing while Forces or its arrows are off', () => {
    const layer = createForceLayer();
    expect(layer(DEFAULT_STATE, local)).toBeNull();
    expect(layer(ON, local)).toBeNull();
  });

  it('keeps its setup and scale through the frames of Play (each carries a new design object)', () => {
    const layer = createForceLayer();
    const state = { ...ON, forces: { ...ON.forces, showVectors: true } };
    const first = layer(state, local);
    const frame = { ...state, design: { ...state.design }, motion: { ...state.motion, theta2Deg: 46 } };
    const next = layer(frame, localPose(ON.design.linkage, 46, 'open', ON.design.coupler, false));
    // The same scale object: nothing but the pose was solved again.
    expect(next?.scale).toBe(first?.scale);
    const longer = { ...state, design: { ...state.design, linkage: { ...state.design.linkage, r2: 2.5 } } };
    expect(layer(longer, local)?.scale).not.toBe(first?.scale);
  });

  it('puts F12 at O2, F32 at A, F43 at B and F14 at O4, as the solver gives them', () => {
    const layer = createForceLayer();
    const state = { ...ON, forces: { ...ON.forces, showVectors: true } };
    const f = layer(state, local);
    const p = poseForces(forceSetup(state), local.theta2Rad, local.pose).forces!;
    expect(f?.pins).toEqual({ O2: p.F12, A: p.F32, B: p.F43, O4: p.F14 });
    expect(f?.scale?.value).toBeGreaterThan(0);
    expect(f?.text.label.O2).toBe('F12');
  });
});

describe('forces past the double range (status overflow)', () => {
  const MASSLESS = { mass: 0, inertia: 0, cg: { dist: 0, angle: 0 } };
  const base = forceSetup(ON);

  it('says at a pose that a force passes the number range, in English and zh-TW, never a limit position', () => {
    // An unbalanced crank: |F12| = m d ω2² = 1e300 · 0.15 · 1e20, past 1.8e308 (tests/solver/forcesOverflow.test.ts).
    const crank = { mass: 1e300, inertia: 0, cg: { dist: 0.15, angle: 0 } };
    const setup = {
      ...base,
      linkage: { r1: 0.6, r2: 0.3, r3: 0.4, r4: 0.5 },
      inertia: { crank, coupler: MASSLESS, rocker: MASSLESS },
      loads: {},
      input: { omega2: 1e10, alpha2: 0 },
    };
    const local = localPose(setup.linkage, 40, 'open', ON.design.coupler, false);
    const p = poseForces(setup, local.theta2Rad, local.pose);
    expect(p.status).toBe('overflow');
    for (const f of poseFacts(p, t)) expect(f.value).toBe(MISSING);
    expect(poseReason(p, t)).toBe(t.overflowReason);
    expect(poseReason(p, zh)).toBe(zh.overflowReason);
    expect(t.overflowReason).toMatch(/number range/);
    expect(zh.overflowReason).toMatch(/[\u4e00-\u9fff]/);
    expect(zh.overflowReason).not.toBe(t.overflowReason);
  });

  it('says why the cycle numbers are missing when the turn overflows', () => {
    const coupler = { mass: 1e300, inertia: 1e300, cg: { dist: 0.2, angle: 0.1 } };
    const setup = {
      ...base,
      linkage: { r1: 0.6, r2: 0.2, r3: 0.5, r4: 0.45 },
      inertia: { crank: MASSLESS, coupler, rocker: MASSLESS },
      loads: {},
      input: { omega2: 1e6, alpha2: 0 },
    };
    const c = cycleForces(setup, 'open', 360);
    expect(c?.status).toBe('overflow');
    const f = cycleFacts(c, 1e6, t);
    expect(f.mean).toBe(MISSING);
    expect(f.reason).toBe(t.cycleGaps.overflow);
    expect(cycleFacts(c, 1e6, zh).reason).toBe(zh.cycleGaps.overflow);
    expect(zh.cycleGaps.overflow).toMatch(/[\u4e00-\u9fff]/);
  });
});
