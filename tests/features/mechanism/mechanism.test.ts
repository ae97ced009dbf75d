import Decimal from 'decimal.js';
import { csvParseRows } from 'd3-dsv';
import { describe, expect, it } from 'vitest';
import { MECHANISM_TEMPLATES, fourBarSpec, sliderCrankSpec, sweepMechanism } from '../../../src/mechanism';
import type { MechanismSpec } from '../../../src/mechanism';
import {
  LIMIT_TOLERANCE,
  analyseMechanism,
  assembledRun,
  inputGrid,
  runRange,
} from '../../../src/features/mechanism/mechAnalysis';
import { csvHeader, csvInputs, mechCsv } from '../../../src/features/mechanism/mechCsv';
import { drawnPose, poseAt } from '../../../src/features/mechanism/mechPose';
import { advanceInput } from '../../../src/features/mechanism/mechDriveStep';
import {
  addJoint,
  addLink,
  deleteJoint,
  deleteLink,
  emptySpec,
  makeGround,
  renameJoint,
  renameLink,
} from '../../../src/features/mechanism/specEdits';
import { defaultPlots, plotValues } from '../../../src/features/mechanism/mechPlots';

Decimal.set({ precision: 40 });

/** The offset slider-crank of the templates: crank 2, rod 5, slider on y = 1, drawn at crank angle 0. */
const SLIDER_CRANK = MECHANISM_TEMPLATES.sliderCrank.spec;

/** B.x of the offset slider-crank at crank angle θ (40 digits): A = 2 (cos θ, sin θ), B.x = A.x + √(25 − (1 − A.y)²). */
function sliderX(theta: number): number {
  const t = new Decimal(theta);
  const ax = Decimal.cos(t).times(2);
  const ay = Decimal.sin(t).times(2);
  return ax.plus(new Decimal(25).minus(new Decimal(1).minus(ay).pow(2)).sqrt()).toNumber();
}

/** dB.x/dθ of the same, by the chain rule in 40 digits: −2 sin θ + (1 − A.y)·2 cos θ / √(25 − (1 − A.y)²). */
function sliderVx(theta: number): number {
  const t = new Decimal(theta);
  const ay = Decimal.sin(t).times(2);
  const root = new Decimal(25).minus(new Decimal(1).minus(ay).pow(2)).sqrt();
  return Decimal.sin(t)
    .times(-2)
    .plus(new Decimal(1).minus(ay).times(Decimal.cos(t).times(2)).div(root))
    .toNumber();
}

describe('csvInputs', () => {
  it('gives a full turn of a pin 360 rows in 1° steps, the first at 0', () => {
    const x = csvInputs('R', [-Math.PI, Math.PI], true);
    expect(x).toHaveLength(360);
    expect(x[0]).toBe(0);
    expect(x[359]).toBeCloseTo((359 * Math.PI) / 180, 15);
  });

  it('gives a rocking pin its whole degrees within the range, and a slider 361 slides', () => {
    const r = csvInputs('R', [(-20.5 * Math.PI) / 180, (30 * Math.PI) / 180], false);
    expect(r[0]).toBeCloseTo((-20 * Math.PI) / 180, 15);
    expect(r).toHaveLength(51);
    const p = csvInputs('P', [-1, 2], false);
    expect(p).toHaveLength(361);
    expect([p[0], p[360]]).toEqual([-1, 2]);
  });
});

describe('mechCsv', () => {
  it('writes the issue’s columns: input, then id_x, id_y (and the rates) per joint and tracer in spec order', () => {
    expect(csvHeader(SLIDER_CRANK, false)).toEqual(['input', 'O2_x', 'O2_y', 'A_x', 'A_y', 'B_x', 'B_y', 'S_x', 'S_y']);
    const withTracer = MECHANISM_TEMPLATES.fourBar.spec;
    expect(csvHeader(withTracer, true).slice(-6)).toEqual(['P_x', 'P_y', 'P_vx', 'P_vy', 'P_ax', 'P_ay']);
  });

  it('puts the slider pin where the closed form does, to 1e-12, with its velocity per rad of crank', () => {
    const inputs = csvInputs('R', [-Math.PI, Math.PI], true);
    const sweep = sweepMechanism(SLIDER_CRANK, inputs, { omega: 1, alpha: 0 });
    const rows = csvParseRows(mechCsv(SLIDER_CRANK, inputs, sweep, true));
    const header = rows[0];
    const bx = header.indexOf('B_x');
    const bvx = header.indexOf('B_vx');
    expect(rows).toHaveLength(361);
    for (const k of [0, 1, 45, 90, 135, 180, 225, 300, 359]) {
      const row = rows[k + 1];
      const theta = Number(row[0]);
      expect(theta).toBe(inputs[k]);
      // Lengths of order 5: the engine's rounding is a few ulps; 1e-12 leaves room and catches any wrong pose.
      expect(Math.abs(Number(row[bx]) - sliderX(theta)), `B_x at ${k}°`).toBeLessThan(1e-12);
      expect(Math.abs(Number(row[bvx]) - sliderVx(theta)), `B_vx at ${k}°`).toBeLessThan(1e-9);
    }
  });

  it('leaves a cell empty where the linkage does not assemble, never NaN', () => {
    const inputs = Float64Array.from([0, 0.1, 3]);
    const sweep = sweepMechanism(MECHANISM_TEMPLATES.chebyshev.spec, inputs);
    const text = mechCsv(MECHANISM_TEMPLATES.chebyshev.spec, inputs, sweep, false);
    expect(text).not.toMatch(/NaN/);
    expect(
      csvParseRows(text)[3]
        .slice(1)
        .every((c) => c === ''),
    ).toBe(true);
  });
});

describe('analyseMechanism', () => {
  it('finds that the slider-crank’s crank turns fully, with 0 on the grid exactly', () => {
    const a = analyseMechanism(SLIDER_CRANK);
    expect(a.problem).toBeNull();
    expect(a.fullTurn).toBe(true);
    expect(a.grid!.inputs[-a.grid!.kLo]).toBe(0);
    expect(a.grid!.inputs).toHaveLength(361);
  });

  it('finds the piston-driven crank’s dead centres within one grid step (the piston at l ± r from O2)', () => {
    const spec = MECHANISM_TEMPLATES.pistonDriven.spec;
    const a = analyseMechanism(spec);
    const b0 = spec.joints.find((j) => j.id === 'B')!.x;
    // Dead centres: crank and rod in line, B at x = 7 (outer) and 3 (the crank at π on this branch).
    const [lo, hi] = runRange(a)!;
    const step = a.grid!.step;
    expect(hi).toBeLessThanOrEqual(7 - b0);
    expect(hi).toBeGreaterThan(7 - b0 - step);
    expect(lo).toBeGreaterThanOrEqual(3 - b0);
    expect(lo).toBeLessThan(3 - b0 + step);
    expect(a.fullTurn).toBe(false);
  });

  it('says what stops a linkage: no input, mobility ≠ 1', () => {
    expect(analyseMechanism(emptySpec()).problem).toEqual({ code: 'noInput' });
    const open = deleteJoint(SLIDER_CRANK, 'S');
    expect(analyseMechanism(open).problem).toEqual({ code: 'mobility', mobility: 3 });
    expect(analyseMechanism(open).mobility).toBe(3);
  });
});

describe('assembledRun', () => {
  it('is the run of assembled samples around the drawn one', () => {
    expect(assembledRun([0, 1, 1, 1, 0, 1], 2)).toEqual([1, 3]);
    expect(assembledRun([1, 1, 1], 0)).toEqual([0, 2]);
    expect(assembledRun([1, 0, 1], 1)).toBeNull();
  });
});

describe('poseAt', () => {
  it('is the drawn pose at input 0, and the closed form’s slider between grid points to 1e-4 of the rod', () => {
    const grid = inputGrid(SLIDER_CRANK)!;
    const sweep = sweepMechanism(SLIDER_CRANK, grid.inputs);
    expect(poseAt(SLIDER_CRANK, grid, sweep, 0)!.joints).toEqual(drawnPose(SLIDER_CRANK).joints);
    // Linear interpolation between 1° samples: the error is at most (1°)²/8 times the second derivative (≈ 3).
    for (const t of [0.3, 1.234, -2.5]) {
      expect(Math.abs(poseAt(SLIDER_CRANK, grid, sweep, t)!.joints.B.x - sliderX(t))).toBeLessThan(1e-4 * 5);
    }
  });
});

describe('advanceInput', () => {
  it('wraps a full turn into [−π, π)', () => {
    const s = advanceInput(3, 1, 0.5, [-Math.PI, Math.PI], true);
    expect(s.input).toBeCloseTo(3.5 - 2 * Math.PI, 14);
    expect(s.direction).toBe(1);
    expect(s.limitAt).toBeNull();
  });

  it('reverses at a rocking range’s end and says where', () => {
    expect(advanceInput(0.9, 1, 0.2, [-1, 1], false)).toEqual({ input: 1, direction: -1, limitAt: 1 });
    expect(advanceInput(-0.9, -1, 0.2, [-1, 1], false)).toEqual({ input: -1, direction: 1, limitAt: -1 });
    expect(advanceInput(0, -1, 0.2, [-1, 1], false)).toEqual({ input: -0.2, direction: -1, limitAt: null });
  });
});

describe('spec edits', () => {
  it('build a slider-crank from nothing whose mobility is 1', () => {
    let s: MechanismSpec = emptySpec();
    for (let i = 0; i < 3; i++) s = addLink(s).spec;
    s = addJoint(s, 'R', ['ground', 'link1'], 0, 0).spec;
    s = addJoint(s, 'R', ['link1', 'link2'], 2, 0).spec;
    s = addJoint(s, 'R', ['link2', 'link3'], 6, 1).spec;
    s = addJoint(s, 'P', ['link3', 'ground'], 6, 1).spec;
    s = { ...s, input: { joint: 'J1' } };
    expect(s.joints.map((j) => j.id)).toEqual(['J1', 'J2', 'J3', 'S1']);
    expect(analyseMechanism(s).problem).toBeNull();
  });

  it('rename everywhere, refuse a taken or empty name naming it, and make a link the ground', () => {
    const r = renameJoint(SLIDER_CRANK, 'O2', '曲柄軸');
    expect(r.input.joint).toBe('曲柄軸');
    expect(() => renameJoint(SLIDER_CRANK, 'O2', 'A')).toThrow('name of O2: the name "A" is taken');
    expect(() => renameLink(SLIDER_CRANK, 'crank', ' ')).toThrow('name of crank: a name cannot be empty');
    const g = makeGround(SLIDER_CRANK, 'crank');
    expect(g.joints[0].links).toEqual(['crank', 'ground']);
    expect(g.links).toEqual(['crank', 'ground', 'coupler', 'slider']);
    const d = deleteLink(SLIDER_CRANK, 'coupler');
    expect(d.joints.map((j) => j.id)).toEqual(['O2', 'S']);
    expect(() => deleteLink(SLIDER_CRANK, 'ground')).toThrow(/cannot be deleted/);
  });
});

describe('plotValues', () => {
  it('plots the slider’s slide and the rod’s rotation from as drawn', () => {
    const inputs = Float64Array.from([0, Math.PI / 2]);
    const sweep = sweepMechanism(SLIDER_CRANK, inputs, { omega: 1, alpha: 0 });
    expect(defaultPlots(SLIDER_CRANK)[0]).toBe('slide:S');
    const slide = plotValues({ kind: 'slide', id: 'S' }, sweep);
    expect(slide[0]).toBe(0);
    expect(Math.abs(slide[1] - (sliderX(Math.PI / 2) - sliderX(0)))).toBeLessThan(1e-12);
    const speed = plotValues({ kind: 'speed', id: 'B' }, sweep);
    expect(Math.abs(speed[1] - Math.abs(sliderVx(Math.PI / 2)))).toBeLessThan(1e-9);
  });
});

describe('refineLimits (through analyseMechanism)', () => {
  it('finds a non-Grashof four-bar’s limits to 1e-9 of the turn: |θ2| ≤ acos((r1² + r2² − (r3 + r4)²) / (2 r1 r2))', () => {
    // 4-3-3.5-3 (II-1, a triple rocker): the crank stops where coupler and rocker are in line, at ±135.95°.
    const a = analyseMechanism(fourBarSpec(4, 3, 3.5, 3));
    const [r1, r2, r3, r4] = [4, 3, 3.5, 3].map((x) => new Decimal(x));
    const limit = Decimal.acos(
      r1.pow(2).plus(r2.pow(2)).minus(r3.plus(r4).pow(2)).div(r1.times(r2).times(2)),
    ).toNumber();
    expect(a.fullTurn).toBe(false);
    const [lo, hi] = a.limits!;
    const tol = 2 * LIMIT_TOLERANCE * 2 * Math.PI;
    expect(Math.abs(hi - limit)).toBeLessThan(tol);
    expect(Math.abs(lo + limit)).toBeLessThan(tol);
    // The grid alone knows it to a step (1°).
    const [glo, ghi] = runRange(a)!;
    expect(limit - ghi).toBeGreaterThan(1e-6);
    expect(glo + limit).toBeGreaterThan(1e-6);
  });

  it('finds a slider-crank’s crank limits when the rod is shorter than crank plus offset: sin θ = (e − l) / r', () => {
    // Crank 2, rod 2.5, offset 1: the rod cannot reach the guide below θ where r sin θ = e − l (the rod straight down).
    const a = analyseMechanism(sliderCrankSpec(2, 2.5, 1));
    const [r, l, e] = [2, 2.5, 1].map((x) => new Decimal(x));
    // The crank pin A = r (cos θ, sin θ) must lie within l of the line y = e: r sin θ ≥ e − l.
    const low = Decimal.asin(e.minus(l).div(r)).toNumber();
    const high = Math.PI - low;
    const tol = 2 * LIMIT_TOLERANCE * 2 * Math.PI;
    const [lo, hi] = a.limits!;
    expect(Math.abs(lo - low)).toBeLessThan(tol);
    // Past π the input wraps in the grid (−π, π]: the upper limit π − low lies beyond the grid's end, so the run ends there.
    expect(hi).toBeLessThanOrEqual(Math.PI);
    expect(high).toBeGreaterThan(Math.PI);
  });
});
