/**
 * Every public solver function validates every argument: bad input throws an Error whose message names
 * the parameter and shows the bad value (issue 7, item 6), never a raw TypeError/RangeError, never a
 * silent coercion. Each row below is one misuse; the property test feeds every numeric parameter of
 * every function non-numbers, NaN, +-Infinity, 0 and negatives (fixed seed).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Linkage } from '../../src/solver';
import {
  adaptiveGrid,
  adaptiveSweep,
  angleDiff,
  classify,
  couplerPoint,
  couplerPointMotion,
  degToRad,
  designMetrics,
  inputRange,
  instantCenters,
  linkRates,
  jointPositions,
  loopResidual,
  radToDeg,
  seedFirstGuess,
  solveClosedForm,
  solveNewton,
  sweep,
  sweepRates,
  theta2Grid,
  transmissionAngle,
  validateLinkage,
  velocityRatios,
  wrapAngle,
} from '../../src/solver';

const L: Linkage = { r1: 6, r2: 2, r3: 5, r4: 5 };
const GUESS = { theta3: 0.5, theta4: 1.9 };
const POSE = { theta3: 0.5, theta4: 1.9 };
const GRID = [0, 0.5, 1];
const INPUT = { omega2: 1, alpha2: 0 };
const OK = () => true;

type Call = () => unknown;

/** [what is misused, the call, text the message must contain (parameter name and the value as shown)]. */
const MISUSES: Array<[string, Call, string[]]> = [
  ['sweep theta2s a number', () => sweep(L, 1 as never, { branch: 'open' }), ['theta2s', '1']],
  ['sweep theta2s a Set', () => sweep(L, new Set([1, 2]) as never, { branch: 'open' }), ['theta2s', 'Set']],
  ['sweep theta2s null', () => sweep(L, null as never, { branch: 'open' }), ['theta2s', 'null']],
  ['sweep theta2s undefined', () => sweep(L, undefined as never, { branch: 'open' }), ['theta2s', 'undefined']],
  ['sweep theta2s a string', () => sweep(L, '123' as never, { branch: 'open' }), ['theta2s', '"123"']],
  ['sweep theta2s {length: -1}', () => sweep(L, { length: -1 } as never, { branch: 'open' }), ['theta2s.length', '-1']],
  [
    'sweep theta2s {length: 1.5}',
    () => sweep(L, { length: 1.5 } as never, { branch: 'open' }),
    ['theta2s.length', '1.5'],
  ],
  ['sweep theta2s with NaN', () => sweep(L, [0, NaN], { branch: 'open' }), ['theta2s[1]', 'NaN']],
  ['sweep theta2s with a string', () => sweep(L, [0, '1'] as never, { branch: 'open' }), ['theta2s[1]', '"1"']],
  ['sweep theta2s a BigInt64Array', () => sweep(L, new BigInt64Array(2) as never, { branch: 'open' }), ['theta2s[0]']],
  ['sweep opts undefined', () => sweep(L, GRID, undefined as never), ['opts', 'undefined']],
  ['sweep opts null', () => sweep(L, GRID, null as never), ['opts', 'null']],
  ['sweep opts a string', () => sweep(L, GRID, 'open' as never), ['opts', '"open"']],
  ['sweep branch missing', () => sweep(L, GRID, {} as never), ['branch', 'undefined']],
  ['sweep branch wrong', () => sweep(L, GRID, { branch: 'up' as never }), ['branch', '"up"']],
  ['sweep method null', () => sweep(L, GRID, { branch: 'open', method: null as never }), ['method', 'null']],
  ['sweep method unknown', () => sweep(L, GRID, { branch: 'open', method: 'euler' as never }), ['method', '"euler"']],
  ['sweep tol NaN', () => sweep(L, GRID, { branch: 'open', method: 'newton', tol: NaN }), ['tol', 'NaN']],
  ['sweep tol 0', () => sweep(L, GRID, { branch: 'open', method: 'newton', tol: 0 }), ['tol', '0']],
  ['sweep tol negative', () => sweep(L, GRID, { branch: 'open', method: 'seed', tol: -1 }), ['tol', '-1']],
  ['sweep tol a string', () => sweep(L, GRID, { branch: 'open', tol: '1e-9' as never }), ['tol', '"1e-9"']],
  ['sweep polish a string', () => sweep(L, GRID, { branch: 'open', polish: 'no' as never }), ['polish', '"no"']],
  ['sweep linkage null', () => sweep(null as never, GRID, { branch: 'open' }), ['linkage', 'null']],
  ['solveNewton opts null', () => solveNewton(L, 0, GUESS, null as never), ['opts', 'null']],
  ['solveNewton seed a string', () => solveNewton(L, 0, GUESS, { seed: 'yes' as never }), ['seed', '"yes"']],
  ['solveNewton polish a string', () => solveNewton(L, 0, GUESS, { polish: 'no' as never }), ['polish', '"no"']],
  ['solveNewton log a number', () => solveNewton(L, 0, GUESS, { log: 1 as never }), ['log', '1']],
  ['solveNewton tol NaN', () => solveNewton(L, 0, GUESS, { tol: NaN }), ['tol', 'NaN']],
  ['solveNewton tol Infinity', () => solveNewton(L, 0, GUESS, { tol: Infinity }), ['tol', 'Infinity']],
  ['solveNewton maxIterations 1.5', () => solveNewton(L, 0, GUESS, { maxIterations: 1.5 }), ['maxIterations', '1.5']],
  [
    'solveNewton maxIterations 1e9',
    () => solveNewton(L, 0, GUESS, { maxIterations: 1e9 }),
    ['maxIterations', '1000000000'],
  ],
  ['solveNewton guess null', () => solveNewton(L, 0, null as never), ['guess', 'null']],
  ['solveNewton guess.theta4 NaN', () => solveNewton(L, 0, { theta3: 0, theta4: NaN }), ['guess.theta4', 'NaN']],
  ['solveNewton theta2 Infinity', () => solveNewton(L, Infinity, GUESS), ['theta2', 'Infinity']],
  ['solveNewton theta2 a string', () => solveNewton(L, '1' as never, GUESS), ['theta2', '"1"']],
  ['solveClosedForm theta2 NaN', () => solveClosedForm(L, NaN, 'open'), ['theta2', 'NaN']],
  ['solveClosedForm branch null', () => solveClosedForm(L, 0, null as never), ['branch', 'null']],
  ['theta2Grid step 0', () => theta2Grid(0, 360, 0), ['stepDeg', '0']],
  ['theta2Grid step negative', () => theta2Grid(0, 360, -1), ['stepDeg', '-1']],
  ['theta2Grid step NaN', () => theta2Grid(0, 360, NaN), ['stepDeg', 'NaN']],
  ['theta2Grid end Infinity', () => theta2Grid(0, Infinity, 1), ['endDeg', 'Infinity']],
  ['theta2Grid end below start', () => theta2Grid(10, 0, 1), ['endDeg', '0']],
  ['theta2Grid too many points', () => theta2Grid(0, 1e300, 1), ['stepDeg', 'more than']],
  ['adaptiveGrid opts null', () => adaptiveGrid(L, null as never), ['opts', 'null']],
  ['adaptiveGrid endRad Infinity', () => adaptiveGrid(L, { endRad: Infinity }), ['endRad', 'Infinity']],
  ['adaptiveGrid endRad 1.79e308', () => adaptiveGrid(L, { endRad: 1.79e308 }), ['endRad', '1.79e+308']],
  ['adaptiveGrid startRad -1.79e308', () => adaptiveGrid(L, { startRad: -1.79e308 }), ['startRad', '-1.79e+308']],
  ['adaptiveGrid startRad NaN', () => adaptiveGrid(L, { startRad: NaN }), ['startRad', 'NaN']],
  ['adaptiveGrid endRad <= startRad', () => adaptiveGrid(L, { startRad: 1, endRad: 1 }), ['endRad', '1']],
  ['adaptiveGrid pixels NaN', () => adaptiveGrid(L, { pixels: NaN }), ['pixels', 'NaN']],
  ['adaptiveGrid pixels 0', () => adaptiveGrid(L, { pixels: 0 }), ['pixels', '0']],
  ['adaptiveGrid maxJumpRad NaN', () => adaptiveGrid(L, { maxJumpRad: NaN }), ['maxJumpRad', 'NaN']],
  ['adaptiveGrid maxPoints -1', () => adaptiveGrid(L, { maxPoints: -1 }), ['maxPoints', '-1']],
  ['adaptiveGrid branches empty', () => adaptiveGrid(L, { branches: [] }), ['branches', '[]']],
  ['adaptiveGrid branches wrong', () => adaptiveGrid(L, { branches: ['up' as never] }), ['branch', '"up"']],
  ['adaptiveSweep opts undefined', () => adaptiveSweep(L, undefined as never), ['opts', 'undefined']],
  ['adaptiveSweep method null', () => adaptiveSweep(L, { branch: 'open', method: null as never }), ['method', 'null']],
  ['adaptiveSweep branch missing', () => adaptiveSweep(L, {} as never), ['branch', 'undefined']],
  ['seedFirstGuess bad branch', () => seedFirstGuess('both' as never), ['branch', '"both"']],
  ['classify r2 a string', () => classify({ ...L, r2: '2' as never }), ['r2', '"2"']],
  ['inputRange r4 0', () => inputRange({ ...L, r4: 0 }), ['r4', '0']],
  ['validateLinkage array', () => validateLinkage([6, 2, 5, 5]), ['r1', 'undefined']],
  ['jointPositions angles null', () => jointPositions(L, 0, null as never), ['angles', 'null']],
  ['couplerPoint pDist a string', () => couplerPoint(L, 0, 0, '1' as never, 0), ['pDist', '"1"']],
  ['couplerPoint theta3 null', () => couplerPoint(L, 0, null as never, 1, 0), ['theta3', 'null']],
  ['transmissionAngle theta4 missing', () => transmissionAngle({ theta3: 0 } as never), ['angles.theta4', 'undefined']],
  ['velocityRatios theta2 a string', () => velocityRatios(L, '0' as never, POSE), ['theta2', '"0"']],
  ['loopResidual r1 -1', () => loopResidual({ ...L, r1: -1 }, 0, POSE), ['r1', '-1']],
  ['wrapAngle a string', () => wrapAngle('1' as never), ['wrapAngle', '1']],
  ['angleDiff an object', () => angleDiff({} as never, 1), ['angleDiff']],
  ['degToRad a string', () => degToRad('90' as never), ['deg', '"90"']],
  ['radToDeg null', () => radToDeg(null as never), ['rad', 'null']],
  ['sweepRates theta2 null', () => sweepRates(L, null as never, [0], [0], OK, INPUT), ['theta2', 'null']],
  ['sweepRates theta3 a number', () => sweepRates(L, [0], 1 as never, [0], OK, INPUT), ['theta3', '1']],
  ['sweepRates theta3 strings', () => sweepRates(L, [0], ['0.5'] as never, [1.9], OK, INPUT), ['theta3[0]', '"0.5"']],
  ['sweepRates {length: 2}', () => sweepRates(L, { length: 2 }, [0, 0], [0, 0], OK, INPUT), ['theta2[0]', 'undefined']],
  ['sweepRates theta2 NaN where ok', () => sweepRates(L, [NaN], [0.5], [1.9], OK, INPUT), ['theta2[0]', 'NaN']],
  [
    'sweepRates theta4 Infinity where ok',
    () => sweepRates(L, [0, 1], [0.5, 0.5], [1.9, Infinity], OK, INPUT),
    ['theta4[1]', 'Infinity'],
  ],
  ['sweepRates ok not a function', () => sweepRates(L, [0], [0.5], [1.9], true as never, INPUT), ['ok', 'true']],
  ['sweepRates input null', () => sweepRates(L, [0], [0.5], [1.9], OK, null as never), ['input', 'null']],
  ['sweepRates linkage null', () => sweepRates(null as never, [0], [0.5], [1.9], OK, INPUT), ['linkage', 'null']],
  ['linkRates pose a string', () => linkRates(L, 0, 'pose' as never, INPUT), ['pose', '"pose"']],
  ['linkRates theta2 an object', () => linkRates(L, {} as never, POSE, INPUT), ['theta2', '{}']],
  [
    'linkRates input.omega2 a string',
    () => linkRates(L, 0, POSE, { omega2: '1' as never, alpha2: 0 }),
    ['input.omega2', '"1"'],
  ],
  [
    'couplerPointMotion pAngle a string',
    () => couplerPointMotion(L, 0, POSE, INPUT, 1, '0' as never),
    ['pAngle', '"0"'],
  ],
  ['instantCenters pose a string', () => instantCenters(L, 0, 'pose' as never), ['pose', '"pose"']],
  ['instantCenters theta2 an object', () => instantCenters(L, {} as never, POSE), ['theta2', '{}']],
  [
    'instantCenters pose.theta3 a string',
    () => instantCenters(L, 0, { theta3: '1', theta4: 0 } as never),
    ['pose.theta3', '"1"'],
  ],
  ['designMetrics branch a number', () => designMetrics(L, 1 as never), ['branch', '1']],
];

describe('sweepRates', () => {
  it('takes NaN angles where ok(i) is false (a point the sweep did not solve) and gives NaN rates there', () => {
    const r = sweepRates(L, [0, 1], [NaN, 0.5], [NaN, 1.9], (i) => i === 1, INPUT);
    expect(r.omega3[0]).toBeNaN();
    expect(Number.isFinite(r.omega3[1])).toBe(true);
  });
});

describe('the kinematics functions', () => {
  it('take a missing pose (NaN angles) and give NaN points and ratios, which callers read as no pose', () => {
    const p = jointPositions(L, 0, { theta3: NaN, theta4: 0 });
    expect(Number.isNaN(p.B.x)).toBe(true);
    expect(Number.isNaN(couplerPoint(L, 0, NaN, 1, 0).x)).toBe(true);
    expect(Number.isNaN(transmissionAngle({ theta3: NaN, theta4: 0 }))).toBe(true);
    expect(Number.isNaN(velocityRatios(L, NaN, POSE).dTheta3)).toBe(true);
  });
});

describe('every public solver function', () => {
  it.each(MISUSES)('throws a clear Error for %s', (_name, call, parts) => {
    let thrown: unknown = null;
    try {
      call();
    } catch (e) {
      thrown = e;
    }
    expect(thrown, 'expected an Error').toBeInstanceOf(Error);
    expect((thrown as Error).constructor, 'a plain Error, not a raw TypeError/RangeError').toBe(Error);
    for (const p of parts) expect((thrown as Error).message).toContain(p);
  });

  it('names the parameter for non-numbers, NaN, +-Infinity, 0 and negatives in every numeric parameter', () => {
    const bad = fc.constantFrom<unknown>(NaN, Infinity, -Infinity, 0, -1, -1e-300, '1', null, undefined, {}, [], true);
    const positive = new Set(['r1', 'r2', 'r3', 'r4', 'tol', 'pixels', 'maxJumpRad', 'stepDeg']);
    /** [parameter, call with the value put in that parameter]. */
    const slots: Array<[string, (v: unknown) => unknown]> = [
      ['r1', (v) => classify({ ...L, r1: v as number })],
      ['r2', (v) => sweep({ ...L, r2: v as number }, GRID, { branch: 'open' })],
      ['r3', (v) => solveNewton({ ...L, r3: v as number }, 0, GUESS)],
      ['r4', (v) => adaptiveGrid({ ...L, r4: v as number })],
      ['theta2', (v) => solveClosedForm(L, v as number, 'open')],
      ['theta2', (v) => solveNewton(L, v as number, GUESS)],
      ['guess.theta3', (v) => solveNewton(L, 0, { theta3: v as number, theta4: 1 })],
      ['tol', (v) => sweep(L, GRID, { branch: 'open', method: 'newton', tol: v as number })],
      ['tol', (v) => solveNewton(L, 0, GUESS, { tol: v as number })],
      ['pixels', (v) => adaptiveGrid(L, { pixels: v as number })],
      ['maxJumpRad', (v) => adaptiveGrid(L, { maxJumpRad: v as number })],
      ['startRad', (v) => adaptiveGrid(L, { startRad: v as number, endRad: 10 })],
      ['stepDeg', (v) => theta2Grid(0, 10, v as number)],
      ['startDeg', (v) => theta2Grid(v as number, 10, 1)],
      ['theta2s[0]', (v) => sweep(L, [v as number], { branch: 'open' })],
    ];
    fc.assert(
      fc.property(fc.constantFrom(...slots), bad, ([name, call], v) => {
        // Values the parameter legitimately accepts: undefined for options, 0 / negatives where any finite is fine.
        const optional = ['tol', 'pixels', 'maxJumpRad', 'startRad'].includes(name) && v === undefined;
        const finiteOk = typeof v === 'number' && Number.isFinite(v) && !positive.has(name);
        if (optional || finiteOk) {
          call(v);
          return;
        }
        let thrown: unknown = null;
        try {
          call(v);
        } catch (e) {
          thrown = e;
        }
        expect(thrown, `${name} = ${String(v)} was accepted`).toBeInstanceOf(Error);
        expect((thrown as Error).constructor).toBe(Error);
        expect((thrown as Error).message).toContain(name);
      }),
      { seed: 7, numRuns: 400 },
    );
  });
});
