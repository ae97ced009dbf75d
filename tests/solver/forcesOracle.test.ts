/**
 * linkForces against the independent 40-digit Newton–Euler oracle (tests/solver/forcesOracle.ts: its own
 * positions, rates and a 9x9 Gaussian elimination). Errors are fractions of the problem's force scale W
 * (the largest pin force, or the largest inertia force, weight, applied force or moment over its arm
 * when the pin forces cancel to less), torques and moments over W times the longest lever arm.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { linkForces, linkRates, solveClosedForm } from '../../src/solver';
import { decades, forceCaseArb, forceError, leverArm, oracleForces, uniform } from './forcesOracle';

const EPS = Number.EPSILON;

describe('linkForces against the 40-digit Newton–Euler oracle', () => {
  it('matches on random cases with the positions and rates solved by the oracle (seeded)', () => {
    // The solver's pose carries up to a few eps / |sin mu| of rounding (the position problem's condition),
    // and the forces amplify a change of pose by another 1 / |sin mu|: K eps / sin² mu with K = 32. Measured
    // over these 500 cases: 3 eps / sin² mu, and 2.5e-15 where |sin mu| >= 0.2 (over 3000 cases of the same
    // generator: 5.5 eps / sin² mu and 1.4e-14).
    let worstWellConditioned = 0;
    fc.assert(
      fc.property(forceCaseArb, (c) => {
        const pose = solveClosedForm(c.l, c.theta2, c.branch);
        const ref = oracleForces(c.l, c.theta2, c.branch, c.motion, c.inertia, c.loads);
        if (!pose || !ref || Math.abs(ref.sinMu) < 1e-3) return;
        const got = linkForces(c.l, c.theta2, pose, c.motion, c.inertia, c.loads);
        const err = forceError(got, ref, leverArm(c));
        const tol = (32 * EPS) / ref.sinMu ** 2;
        expect(err, `${JSON.stringify(c)}: error ${err} (sin mu ${ref.sinMu})`).toBeLessThanOrEqual(tol);
        if (Math.abs(ref.sinMu) >= 0.2) worstWellConditioned = Math.max(worstWellConditioned, err);
      }),
      { seed: 20, numRuns: 500 },
    );
    expect(worstWellConditioned).toBeLessThanOrEqual(1e-12);
  });

  it('matches within 1e-13 of the largest force at poses up to 1e-12 rad from a toggle, near 0 and near pi', () => {
    // The pose is taken as exact by both (the loop need not close): what is left is the rates' and the force
    // equations' own rounding. The pin forces there grow like 1 / |sin mu| (statics) and faster with the
    // rates (omega3 and omega4 like 1 / |sin mu|, their accelerations like 1 / |sin mu|³), yet the error stays a
    // few eps of the largest force (measured 195 eps with the oracle's rates, 25 eps with the solver's),
    // because sin mu is formed from the exact angle difference and F43 along the link directions.
    const nearToggle = fc.record({
      c: forceCaseArb,
      theta3: uniform(-Math.PI, Math.PI),
      folded: fc.boolean(),
      gap: fc.tuple(decades(1e-12, 1e-2), fc.constantFrom(1, -1)).map(([g, s]) => g * s),
    });
    fc.assert(
      fc.property(nearToggle, ({ c, theta3, folded, gap }) => {
        const pose = { theta3, theta4: theta3 + (folded ? Math.PI : 0) + gap };
        const got = linkForces(c.l, c.theta2, pose, c.motion, c.inertia, c.loads);
        const ownRates = oracleForces(c.l, c.theta2, pose, c.motion, c.inertia, c.loads);
        const rates = linkRates(c.l, c.theta2, pose, c.motion);
        const givenRates = oracleForces(c.l, c.theta2, { ...pose, rates }, c.motion, c.inertia, c.loads);
        if (!ownRates || !givenRates) return;
        const ctx = `${JSON.stringify({ c, pose })} (sin mu ${ownRates.sinMu})`;
        expect(forceError(got, ownRates, leverArm(c)), `${ctx}: oracle's rates`).toBeLessThanOrEqual(1e-13);
        expect(forceError(got, givenRates, leverArm(c)), `${ctx}: solver's rates`).toBeLessThanOrEqual(1e-13);
      }),
      { seed: 21, numRuns: 300 },
    );
  });
});
