/**
 * Validates the 60-digit oracle itself against the published table of hard cases (docs/hard-cases.md),
 * independently of the solver. The table prints 10 decimals of a degree, so agreement to 1e-9 deg
 * (a tenth of the last printed digit's rounding band plus slack) is the most it can confirm.
 */
import { describe, expect, it } from 'vitest';
import type { LinkLengths, Sigma } from './reference';
import {
  angleDiff,
  deg,
  exact,
  exactToDeg,
  referenceAngles,
  referenceLimits,
  referenceResidual,
  referenceRockerSwing,
  referenceSlack,
  referenceSolve,
} from './reference';

/** Printed precision of the table: 10 decimals of a degree. */
const TABLE_TOL_DEG = 1e-9;

function nextUp(x: number): number {
  const f = new Float64Array([x]);
  const b = new BigInt64Array(f.buffer);
  b[0] += x >= 0 ? 1n : -1n;
  return f[0];
}

interface TableRow {
  name: string;
  l: LinkLengths;
  theta2: number;
  sigma: Sigma;
  /** Expected (theta3, theta4) in degrees as printed in the table. */
  deg: [number, number];
}

const case1: LinkLengths = { r1: 6, r2: 2, r3: 5, r4: 5 };

const rows: TableRow[] = [
  { name: 'case 1 at 0, open', l: case1, theta2: 0, sigma: 1, deg: [66.4218215218, 113.5781784782] },
  { name: 'case 1 at 0, crossed', l: case1, theta2: 0, sigma: -1, deg: [-66.4218215218, -113.5781784782] },
  { name: 'case 1 at 90, open', l: case1, theta2: deg(90), sigma: 1, deg: [32.3335306935, 110.7965716607] },
  { name: 'case 1 at 90, crossed', l: case1, theta2: deg(90), sigma: -1, deg: [-69.2034283393, -147.6664693065] },
  { name: 'case 1 at 180, open', l: case1, theta2: deg(180), sigma: 1, deg: [36.8698976458, 143.1301023542] },
  { name: 'case 1 at 180, crossed', l: case1, theta2: deg(180), sigma: -1, deg: [-36.8698976458, -143.1301023542] },
  {
    name: 'case 2 at 180',
    l: { r1: 4, r2: 1, r3: 3, r4: 2 + 1e-9 },
    theta2: Math.PI,
    sigma: 1,
    deg: [0.0009356362, 179.9985965457],
  },
  {
    name: 'case 2 at 180, crossed',
    l: { r1: 4, r2: 1, r3: 3, r4: 2 + 1e-9 },
    theta2: Math.PI,
    sigma: -1,
    deg: [-0.0009356362, -179.9985965457],
  },
  {
    name: 'case 3 at 0',
    l: { r1: 5, r2: 1, r3: 6, r4: 2 + 1e-9 },
    theta2: 0,
    sigma: 1,
    deg: [0.0007396854, 0.0022190561],
  },
  {
    name: 'case 5 at 180',
    l: { r1: 4, r2: 1, r3: 3, r4: 2 + 1e-12 },
    theta2: Math.PI,
    sigma: 1,
    deg: [2.95887e-5, 179.9999556169],
  },
  {
    name: 'case 7 antiparallelogram at 90',
    l: { r1: 4, r2: 2, r3: 4, r4: 2 },
    theta2: deg(90),
    sigma: -1,
    deg: [-53.1301023542, -143.1301023542],
  },
  { name: 'case 7 parallelogram at 90', l: { r1: 4, r2: 2, r3: 4, r4: 2 }, theta2: deg(90), sigma: 1, deg: [0, 90] },
  {
    name: 'case 8 at 90, open',
    l: { r1: 2, r2: 2, r3: 4, r4: 4 },
    theta2: deg(90),
    sigma: 1,
    deg: [24.2951889454, 65.7048110546],
  },
  {
    name: 'case 8 at 90, crossed',
    l: { r1: 2, r2: 2, r3: 4, r4: 4 },
    theta2: deg(90),
    sigma: -1,
    deg: [-114.2951889454, -155.7048110546],
  },
  {
    name: 'case 9 kite at 90',
    l: { r1: 4, r2: 2, r3: 2, r4: 4 },
    theta2: deg(90),
    sigma: 1,
    deg: [36.8698976458, 126.8698976458],
  },
  { name: 'case 9 folded at 90', l: { r1: 4, r2: 2, r3: 2, r4: 4 }, theta2: deg(90), sigma: -1, deg: [-90, 180] },
  {
    name: 'case 10 at 0',
    l: { r1: 4, r2: 3, r3: 3.5, r4: 3 },
    theta2: 0,
    sigma: 1,
    deg: [52.6168015821, 67.975687163],
  },
  {
    name: 'case 11 at 180',
    l: { r1: 3, r2: 2.5, r3: 4.2, r4: 1.5 },
    theta2: Math.PI,
    sigma: 1,
    deg: [8.9299764871, 154.2378459017],
  },
  {
    name: 'case 12 at 60, open',
    l: { r1: 4, r2: 3, r3: 1, r4: 3.5 },
    theta2: deg(60),
    sigma: 1,
    deg: [29.8530370636, 117.8063239659],
  },
  {
    name: 'case 12 at 60, crossed',
    l: { r1: 4, r2: 3, r3: 1, r4: 3.5 },
    theta2: deg(60),
    sigma: -1,
    deg: [-122.0572645675, 149.9894485301],
  },
  {
    name: 'case 13 at fl(pi/2), open',
    l: { r1: 4, r2: 3, r3: 2.5, r4: 2.5 },
    theta2: Math.PI / 2,
    sigma: 1,
    deg: [-36.8698972066, 143.1301019149],
  },
  {
    name: 'case 13 at fl(pi/2), crossed',
    l: { r1: 4, r2: 3, r3: 2.5, r4: 2.5 },
    theta2: Math.PI / 2,
    sigma: -1,
    deg: [-36.8698980851, 143.1301027934],
  },
  {
    name: 'case 14 at pi/3 + 1e-8, open',
    l: { r1: 1, r2: 2, r3: Math.sqrt(5.25), r4: 1.5 },
    theta2: Math.PI / 3 + 1e-8,
    sigma: 1,
    deg: [-49.1066047779, 9.549e-7],
  },
  {
    name: 'case 14 at pi/3 + 1e-8, crossed',
    l: { r1: 1, r2: 2, r3: Math.sqrt(5.25), r4: 1.5 },
    theta2: Math.PI / 3 + 1e-8,
    sigma: -1,
    deg: [-130.8933940762, -179.999999809],
  },
  {
    name: 'case 15 at 0',
    l: { r1: 1, r2: 1e-6, r3: 1, r4: 1 },
    theta2: 0,
    sigma: 1,
    deg: [60.0000330797, 119.9999669203],
  },
  {
    name: 'case 16 at 0',
    l: { r1: 1e6, r2: 1, r3: 1e6 + 0.5, r4: 2 },
    theta2: 0,
    sigma: 1,
    deg: [7.57952e-5, 41.4096600069],
  },
  {
    name: 'case 16 at 90, open',
    l: { r1: 1e6, r2: 1, r3: 1e6 + 0.5, r4: 2 },
    theta2: deg(90),
    sigma: 1,
    deg: [5.3657e-5, 75.5225007884],
  },
  {
    name: 'case 17 (case 1 x 1e200) at 90',
    l: { r1: 6e200, r2: 2e200, r3: 5e200, r4: 5e200 },
    theta2: deg(90),
    sigma: 1,
    deg: [32.3335306935, 110.7965716607],
  },
  {
    name: 'case 18 (case 1 x 1e-200) at 90',
    l: { r1: 6e-200, r2: 2e-200, r3: 5e-200, r4: 5e-200 },
    theta2: deg(90),
    sigma: -1,
    deg: [-69.2034283393, -147.6664693065],
  },
  {
    name: 'case 19 at 0',
    l: { r1: 6, r2: 1e-300, r3: 5, r4: 5 },
    theta2: 0,
    sigma: 1,
    deg: [53.1301023542, 126.8698976458],
  },
  {
    name: 'case 19 at 123',
    l: { r1: 6, r2: 1e-300, r3: 5, r4: 5 },
    theta2: deg(123),
    sigma: -1,
    deg: [-53.1301023542, -126.8698976458],
  },
  {
    name: 'case 20 at fl(pi/3), open',
    l: { r1: 1, r2: 1, r3: 1e-9, r4: 1 },
    theta2: Math.PI / 3,
    sigma: 1,
    deg: [30.0000056695, 119.9999999427],
  },
  { name: 'case 22 at 0, open', l: { r1: 6, r2: 1, r3: 2, r4: 3 }, theta2: 0, sigma: 1, deg: [0, 180] },
  { name: 'case 22 at 0, crossed', l: { r1: 6, r2: 1, r3: 2, r4: 3 }, theta2: 0, sigma: -1, deg: [0, 180] },
];

describe('exact', () => {
  it('takes a double as the binary value it holds, not its shortest decimal', () => {
    // fl(0.1) = 0.1000000000000000055511151231257827021181583404541015625
    expect(exact(0.1).minus('0.1000000000000000055511151231257827021181583404541015625').abs().lessThan('1e-50')).toBe(
      true,
    );
    expect(exact(Math.PI).toString().startsWith('3.14159265358979311599796346854')).toBe(true);
    expect(exact(1e-300).div('1e-300').minus(1).abs().lessThan('1e-15')).toBe(true);
    expect(exact(-2.5).toNumber()).toBe(-2.5);
  });
});

describe('angleDiff', () => {
  it('wraps the difference to (-pi, pi]', () => {
    expect(angleDiff(Math.PI - 1e-3, -Math.PI + 1e-3)).toBeCloseTo(-2e-3, 15);
    expect(angleDiff(-Math.PI + 1e-3, Math.PI - 1e-3)).toBeCloseTo(2e-3, 15);
    expect(angleDiff(1, 1)).toBe(0);
    expect(angleDiff(7 * Math.PI, 0)).toBeCloseTo(Math.PI, 12);
  });
});

describe('referenceAngles', () => {
  it.each(rows)('reproduces the table: $name', ({ l, theta2, sigma, deg: [t3, t4] }) => {
    const pose = referenceAngles(l, theta2, sigma);
    expect(pose).not.toBeNull();
    // Compare through a wrapped difference: 180 and -180 are the same rocker angle.
    const d3 = angleDiff(exactToDeg(pose!.theta3) * (Math.PI / 180), t3 * (Math.PI / 180)) * (180 / Math.PI);
    const d4 = angleDiff(exactToDeg(pose!.theta4) * (Math.PI / 180), t4 * (Math.PI / 180)) * (180 / Math.PI);
    expect(Math.abs(d3)).toBeLessThanOrEqual(TABLE_TOL_DEG);
    expect(Math.abs(d4)).toBeLessThanOrEqual(TABLE_TOL_DEG);
  });

  it.each(rows)('closes the loop and has sign(sin mu) = sigma: $name', ({ l, theta2, sigma }) => {
    const pose = referenceAngles(l, theta2, sigma)!;
    const size = l.r1 + l.r2 + l.r3 + l.r4;
    // The only error left is rounding the 60-digit angles to double: |r| * ulp(angle) ~ 1e-16 size.
    expect(referenceResidual(l, theta2, pose.theta3, pose.theta4) / size).toBeLessThan(2e-16);
    if (Math.abs(pose.sinMu) > 1e-30) expect(Math.sign(pose.sinMu)).toBe(sigma);
  });

  it("reports the table's unreachable inputs as unreachable", () => {
    expect(referenceSolve({ r1: 4, r2: 1, r3: 3, r4: 2 - 1e-12 }, Math.PI, 1).kind).toBe('unreachable');
    expect(referenceSolve({ r1: 4, r2: 3, r3: 3.5, r4: 3 }, deg(136), 1).kind).toBe('unreachable');
    expect(referenceSolve({ r1: 4, r2: 3, r3: 2.5, r4: 2.5 }, nextUp(Math.PI / 2), -1).kind).toBe('unreachable');
    expect(referenceSolve({ r1: 6, r2: 1, r3: 2, r4: 3 }, 1e-8, 1).kind).toBe('unreachable');
    for (let d = -180; d <= 180; d += 15) {
      expect(referenceSolve({ r1: 10, r2: 1, r3: 2, r4: 3 }, deg(d), 1).kind).toBe('unreachable');
    }
  });

  it('reports the case-8 crank pin on O4 as a continuum', () => {
    expect(referenceSolve({ r1: 2, r2: 2, r3: 4, r4: 4 }, 0, 1).kind).toBe('continuum');
  });

  it('puts the next double above pi/2 of case 13 just past the limit (slack < 0, |slack| < 1e-15)', () => {
    const slack = referenceSlack({ r1: 4, r2: 3, r3: 2.5, r4: 2.5 }, nextUp(Math.PI / 2));
    expect(slack).toBeLessThan(0);
    expect(slack).toBeGreaterThan(-1e-15);
    expect(referenceSlack({ r1: 4, r2: 3, r3: 2.5, r4: 2.5 }, Math.PI / 2)).toBeGreaterThan(0);
  });
});

describe('referenceLimits', () => {
  const limitDeg = (x: number) => exactToDeg(x);

  it('gives case 6 an upper limit of 179.9999094034 deg and no lower limit', () => {
    const lim = referenceLimits({ r1: 4, r2: 1, r3: 3, r4: 2 - 1e-12 });
    expect(lim.hasLower).toBe(false);
    expect(lim.hasUpper).toBe(true);
    expect(Math.abs(limitDeg(lim.upperAbs) - 179.9999094034)).toBeLessThan(TABLE_TOL_DEG);
  });

  it('gives case 10 an upper limit of 135.9513743259 deg', () => {
    const lim = referenceLimits({ r1: 4, r2: 3, r3: 3.5, r4: 3 });
    expect(lim.hasLower).toBe(false);
    expect(Math.abs(limitDeg(lim.upperAbs) - 135.9513743259)).toBeLessThan(TABLE_TOL_DEG);
  });

  it('gives case 11 a lower limit of 57.9494901188 deg and no upper limit', () => {
    const lim = referenceLimits({ r1: 3, r2: 2.5, r3: 4.2, r4: 1.5 });
    expect(lim.hasUpper).toBe(false);
    expect(Math.abs(limitDeg(lim.lowerAbs) - 57.9494901188)).toBeLessThan(TABLE_TOL_DEG);
  });

  it('gives case 12 the band [38.6248328731, 78.5848422573] deg', () => {
    const lim = referenceLimits({ r1: 4, r2: 3, r3: 1, r4: 3.5 });
    expect(Math.abs(limitDeg(lim.lowerAbs) - 38.6248328731)).toBeLessThan(TABLE_TOL_DEG);
    expect(Math.abs(limitDeg(lim.upperAbs) - 78.5848422573)).toBeLessThan(TABLE_TOL_DEG);
  });

  it('gives case 13 an upper limit of exactly 90 deg', () => {
    const lim = referenceLimits({ r1: 4, r2: 3, r3: 2.5, r4: 2.5 });
    expect(lim.upperAbs).toBe(Math.PI / 2);
  });

  it('gives case 20 the band 60 +- 6.616e-8 deg', () => {
    const lim = referenceLimits({ r1: 1, r2: 1, r3: 1e-9, r4: 1 });
    expect(Math.abs(limitDeg(lim.lowerAbs) - (60 - 6.616e-8))).toBeLessThan(1e-11);
    expect(Math.abs(limitDeg(lim.upperAbs) - (60 + 6.616e-8))).toBeLessThan(1e-11);
  });

  it('gives a crank-rocker no limit and case 21 an empty range', () => {
    const full = referenceLimits(case1);
    expect(full.hasLower || full.hasUpper || full.empty).toBe(false);
    expect(referenceLimits({ r1: 10, r2: 1, r3: 2, r4: 3 }).empty).toBe(true);
  });
});

describe('referenceRockerSwing', () => {
  it('gives case 1 a rocker swing of 101.537 .. 150.074 deg', () => {
    const swing = referenceRockerSwing(case1);
    expect(Math.abs(exactToDeg(swing.min) - 101.537)).toBeLessThan(5e-4);
    expect(Math.abs(exactToDeg(swing.max) - 150.074)).toBeLessThan(5e-4);
  });
});
