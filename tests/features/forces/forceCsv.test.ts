/**
 * The cycle CSV's force columns (Forces on), checked against two oracles that share nothing with the app's
 * forces code: the 40-digit Newton–Euler oracle of tests/solver/forcesOracle.ts for every column, and the power
 * balance T12 ω2 + P_ext = d(KE)/dt with the motion from the 80-digit differentiated positions
 * (tests/oracle/rates.ts) for the torque. The test converts the design from millimetres and builds the uniform
 * bars (m = ρL, I = mL²/12, CG mid-link) itself.
 */
import { describe, expect, it } from 'vitest';
import { CSV_FORCE_HEADER, CSV_HEADER, CSV_MOTION_HEADER, cycleToCsv } from '../../../src/shared/csv';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import { CYCLE_CSV_FORCE_COLUMNS, csvTable } from '../../shared/csvTable';
import type { AppState } from '../../../src/shared/state/appState';
import { effectiveInputMotion } from '../../../src/shared/state/inputMotion';
import { computeTable } from '../../../src/features/simulator/solve/compute';
import { cycleTableOf } from '../../../src/features/export/exporters';
import { forceColumnsFor } from '../../../src/features/forces/tableForces';
import { referenceMotion } from '../../oracle/rates';
import { oracleForces } from '../../solver/forcesOracle';
import type { OracleInertia, OracleLoads } from '../../solver/forcesOracle';

/** A crank-rocker in millimetres with every load the app offers: 2.5 kg/m bars, gravity, a force at P, a load torque. */
const STATE: AppState = {
  ...DEFAULT_STATE,
  design: {
    ...DEFAULT_STATE.design,
    linkage: { r1: 600, r2: 200, r3: 500, r4: 500 },
    coupler: { distance: 250, angleDeg: 30 },
    lengthUnit: 'mm',
  },
  motion: { ...DEFAULT_STATE.motion, omega2RadPerS: 7.5, alpha2RadPerS2: 20, direction: 1 },
  forces: {
    ...DEFAULT_STATE.forces,
    enabled: true,
    rhoKgPerM: 2.5,
    gravityMPerS2: 9.81,
    pointForceXN: 40,
    pointForceYN: -25,
    loadTorqueNm: -3,
  },
};

/** The same problem in SI, written out by hand: lengths in m, the bars' mass properties, the loads. */
const L = { r1: 0.6, r2: 0.2, r3: 0.5, r4: 0.5 };
const bar = (len: number): OracleInertia => {
  const mass = 2.5 * len;
  return { mass, inertia: (mass * len * len) / 12, cg: { dist: len / 2, angle: 0 } };
};
const INERTIA = { crank: bar(L.r2), coupler: bar(L.r3), rocker: bar(L.r4) };
const P = { dist: 0.25, angle: Math.PI / 6 };
const LOADS: OracleLoads = {
  gravity: { g: 9.81 },
  couplerForce: { pDist: P.dist, pAngle: P.angle, fx: 40, fy: -25 },
  outputTorque: -3,
};
const INPUT = { omega2: 7.5, alpha2: 20 };

/** The CSV the export writes for the state (the path of useExports: the table job, then the force columns). */
function csvOf(state: AppState, samples = 72) {
  const s = state;
  const tbl = computeTable({
    linkage: s.design.linkage,
    samples,
    branch: s.design.branch,
    solver: { method: s.solver.method, tol: s.solver.tol },
    motion: {
      input: effectiveInputMotion(s.motion.omega2RadPerS, s.motion.alpha2RadPerS2, s.motion.direction),
      coupler: { distance: s.design.coupler.distance, angleRad: (s.design.coupler.angleDeg * Math.PI) / 180 },
    },
  });
  const forces = forceColumnsFor(s)?.(tbl) ?? null;
  return csvTable(cycleToCsv({ ...cycleTableOf(tbl), forces }));
}

describe('the cycle CSV with Forces on', () => {
  it('adds torque_Nm, f12x_N … f14y_N after every existing column, at the n samples', () => {
    const { header, data } = csvOf(STATE, 36);
    const without = csvOf({ ...STATE, forces: { ...STATE.forces, enabled: false } }, 36).header;
    expect(header).toEqual([...without, ...CYCLE_CSV_FORCE_COLUMNS]);
    expect(without).toEqual(expect.arrayContaining([...CSV_HEADER, ...CSV_MOTION_HEADER]));
    expect(CSV_FORCE_HEADER).toEqual(header.slice(-9));
    expect(data).toHaveLength(37);
  });

  it('has no force columns while Forces is off', () => {
    const { header } = csvOf({ ...STATE, forces: { ...STATE.forces, enabled: false } }, 12);
    expect(header.some((h) => h.endsWith('_N') || h === 'torque_Nm')).toBe(false);
  });

  it('agrees with the 40-digit Newton–Euler oracle on every column of every row', () => {
    const { data, col } = csvOf(STATE);
    for (const row of data) {
      const theta2 = (col(row, 'theta2_deg') * Math.PI) / 180;
      const ref = oracleForces(L, theta2, 'open', INPUT, INERTIA, LOADS);
      expect(ref).not.toBeNull();
      if (!ref) continue;
      // The scale every column is judged against: the largest pin force. This linkage keeps |sin mu| >= 0.7,
      // so a pose solved to rounding moves the forces by a few eps of it; 1e-10 of it still fails for any wrong
      // term (a unit slip is a factor 1000, a missing load tens of percent).
      const scale = Math.max(...[ref.F12, ref.F32, ref.F43, ref.F14].map((f) => Math.hypot(f.x, f.y)));
      const tol = 1e-10 * scale;
      expect(Math.abs(col(row, 'torque_Nm') - ref.torque)).toBeLessThan(tol * L.r2);
      for (const [name, value] of [
        ['f12x_N', ref.F12.x],
        ['f12y_N', ref.F12.y],
        ['f32x_N', ref.F32.x],
        ['f32y_N', ref.F32.y],
        ['f43x_N', ref.F43.x],
        ['f43y_N', ref.F43.y],
        ['f14x_N', ref.F14.x],
        ['f14y_N', ref.F14.y],
      ] as const) {
        expect(Math.abs(col(row, name) - value), `${name} at ${row[0]}°`).toBeLessThan(tol);
      }
    }
  });

  it('keeps the power balance T12 ω2 + P_ext = d(KE)/dt at every row', () => {
    const { data, col } = csvOf(STATE, 24);
    const g = { x: 0, y: -9.81 };
    for (const row of data) {
      const theta2 = (col(row, 'theta2_deg') * Math.PI) / 180;
      const { omega2: w2, alpha2: a2 } = INPUT;
      // Crank: its CG turns about O2 at r2 / 2.
      const r = { x: (L.r2 / 2) * Math.cos(theta2), y: (L.r2 / 2) * Math.sin(theta2) };
      const v2 = { x: -w2 * r.y, y: w2 * r.x };
      const acc2 = { x: -a2 * r.y - w2 * w2 * r.x, y: a2 * r.x - w2 * w2 * r.y };
      // Coupler CG (mid AB), B (so the rocker's CG, mid O4B, moves at half of B) and P, from the 80-digit oracle.
      const g3 = referenceMotion(L, theta2, 1, INPUT, L.r3 / 2, 0);
      const b = referenceMotion(L, theta2, 1, INPUT, L.r3, 0).point;
      const p = referenceMotion(L, theta2, 1, INPUT, P.dist, P.angle).point;
      const links = [
        { m: INERTIA.crank, v: v2, a: acc2, w: w2, al: a2 },
        {
          m: INERTIA.coupler,
          v: { x: g3.point.vx, y: g3.point.vy },
          a: { x: g3.point.ax, y: g3.point.ay },
          w: g3.omega3,
          al: g3.alpha3,
        },
        {
          m: INERTIA.rocker,
          v: { x: b.vx / 2, y: b.vy / 2 },
          a: { x: b.ax / 2, y: b.ay / 2 },
          w: g3.omega4,
          al: g3.alpha4,
        },
      ];
      let dKE = 0;
      let gravityPower = 0;
      let size = 0;
      for (const k of links) {
        const inertiaTerm = k.m.mass * (k.v.x * k.a.x + k.v.y * k.a.y) + k.m.inertia * k.w * k.al;
        dKE += inertiaTerm;
        gravityPower += k.m.mass * (g.x * k.v.x + g.y * k.v.y);
        size += Math.abs(inertiaTerm) + k.m.mass * 9.81 * Math.hypot(k.v.x, k.v.y);
      }
      const pointPower = 40 * p.vx - 25 * p.vy;
      const loadPower = -3 * g3.omega4;
      const torque = col(row, 'torque_Nm');
      const residual = torque * w2 + gravityPower + pointPower + loadPower - dKE;
      size += Math.abs(torque * w2) + Math.abs(pointPower) + Math.abs(loadPower);
      // Each term is rounded to a few eps of its own size (the oracle's rates carry 80 digits, the CSV 17).
      expect(Math.abs(residual), `at ${row[0]}°`).toBeLessThan(1e-12 * size);
    }
  });
});
