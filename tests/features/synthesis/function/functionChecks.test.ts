import { createElement } from 'react';
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import type { SynFunctionState } from '../../../../src/shared/state/slices/synFunctionSlice';
import { DEFAULT_SYN_FUNCTION } from '../../../../src/shared/state/slices/synFunctionSlice';
import {
  LARGE_ERROR_SHARE,
  solveFunction,
  turningPoint,
} from '../../../../src/features/synthesis/function/functionSolve';
import type { FunctionProblem } from '../../../../src/features/synthesis/function/functionSolve';
import { functionProblemText } from '../../../../src/features/synthesis/function/expressionText';
import { FunctionFacts } from '../../../../src/features/synthesis/function/FunctionFacts';
import { functionMessagesEn } from '../../../../src/features/synthesis/function/functionMessagesEn';
import { functionMessagesZhTw } from '../../../../src/features/synthesis/function/functionMessagesZhTw';
import { messagesEn } from '../../../../src/shared/i18n/messagesEn';
import { functionGenerator } from '../../../../src/synthesis';

const fn = (patch: Partial<SynFunctionState>): SynFunctionState => ({ ...DEFAULT_SYN_FUNCTION, ...patch });
const rad = (deg: number) => (deg * Math.PI) / 180;

/** sin on [−2, 2] with the default angle ranges: functionGenerator finds no defect, yet the error is 17 % of y. */
const SINE = fn({ expression: 'sin(x)', xRange: [-2, 2] });

function noLinkage(s: SynFunctionState, f: (x: number) => number): Extract<FunctionProblem, { code: 'noLinkage' }> {
  const r = solveFunction(s, f);
  if (r.ok || r.problem.code !== 'noLinkage') throw new Error(`expected noLinkage, got ${JSON.stringify(r)}`);
  return r.problem;
}

describe('turningPoint', () => {
  it('finds where sin turns on [0, 3], within one sample of π/2', () => {
    const xs = Array.from({ length: 201 }, (_, k) => (3 * k) / 200);
    const x = turningPoint(
      xs,
      xs.map((v) => Math.sin(v)),
    );
    expect(x).not.toBeNull();
    expect(Math.abs((x as number) - Math.PI / 2)).toBeLessThanOrEqual(3 / 200);
  });

  it('is null for a monotone f, and for steps of rounding size against the direction', () => {
    const xs = Array.from({ length: 101 }, (_, k) => 1 + (9 * k) / 100);
    expect(turningPoint(xs, xs.map(Math.log10))).toBeNull();
    // A flat stretch with a wobble of 1 ulp of 1 is noise, not a turn.
    expect(turningPoint([0, 1, 2, 3], [0, 1, 1 - 2 ** -52, 2])).toBeNull();
    expect(turningPoint([0, 1, 2, 3], [0, 1, 0.9, 2])).toBe(1);
  });
});

describe('solveFunction checks', () => {
  it('has no checks for log10 on [1, 10] (0.66 % error, monotone)', () => {
    const r = solveFunction(DEFAULT_SYN_FUNCTION, Math.log10);
    if (!r.ok) throw new Error('no design');
    expect(r.value.checks).toEqual([]);
  });

  it('says sin on [−2, 2] turns back near −π/2 and that its error is over 5 % of y’s range', () => {
    const r = solveFunction(SINE, Math.sin);
    if (!r.ok) throw new Error('no design');
    // functionGenerator itself sees no defect here: the page's checks are what stop a green "No defects".
    expect(r.value.result.defects).toEqual([]);
    const [turn, large] = r.value.checks;
    expect(turn.code).toBe('notMonotone');
    if (turn.code === 'notMonotone') expect(Math.abs(turn.x + Math.PI / 2)).toBeLessThanOrEqual(4 / 200);
    // The share against y's range computed here: |sin 2 − sin(−2)| = 2 sin 2, and the error from an independent
    // functionGenerator call with 1001 samples (the largest error converges to within 1e-3 of itself).
    const direct = functionGenerator({
      f: Math.sin,
      x: [-2, 2],
      theta2: [rad(30), rad(90)],
      theta4: [rad(-60), rad(-150)],
      points: 3,
      samples: 1001,
    });
    expect(large.code).toBe('largeError');
    if (large.code === 'largeError') {
      expect(large.share).toBeGreaterThan(LARGE_ERROR_SHARE);
      expect(large.share).toBeCloseTo(direct.maxError / (2 * Math.sin(2)), 2);
    }
  });

  it('flags a large error on a monotone f too: tan on [0, 1.2], θ2 0→120°, θ4 60→120° (11 %)', () => {
    const s = fn({ xRange: [0, 1.2], theta2RangeDeg: [0, 120], theta4RangeDeg: [60, 120] });
    const r = solveFunction(s, Math.tan);
    if (!r.ok) throw new Error(JSON.stringify(r.problem));
    // y's range written out here: tan 1.2 − tan 0.
    const share = r.value.result.maxError / Math.tan(1.2);
    expect(share).toBeGreaterThan(0.1);
    expect(r.value.checks).toEqual([{ code: 'largeError', share: expect.closeTo(share, 12) }]);
  });
});

describe('FunctionFacts', () => {
  const render = (s: SynFunctionState, f: (x: number) => number) => {
    const r = solveFunction(s, f);
    if (!r.ok) throw new Error('no design');
    return renderToStaticMarkup(createElement(FunctionFacts, { fd: r.value, fm: functionMessagesEn, t: messagesEn }));
  };

  it('never says "No defects" beside an error over the limit, and names the limit', () => {
    const html = render(SINE, Math.sin);
    expect(html).not.toContain('No defects');
    expect(html).toContain('data-defect="notMonotone"');
    expect(html).toMatch(/Large error: the largest structural error is 16\.\d %.* over 5 %/);
  });

  it('still says "No defects" for log10', () => {
    expect(render(DEFAULT_SYN_FUNCTION, Math.log10)).toContain('No defects');
  });
});

describe('the no-linkage message', () => {
  // Each case: a task with no real linkage and the reason Freudenstein's K's give (checked against the sign of the
  // crank's and rocker's lengths in tests/synthesis/functionGeneration.test.ts).
  const cases: [string, SynFunctionState, (x: number) => number][] = [
    ['exp on [0, 3]', fn({ xRange: [0, 3] }), Math.exp],
    ['log10, θ2 0→10°, θ4 0→170°', fn({ theta2RangeDeg: [0, 10], theta4RangeDeg: [0, 170] }), Math.log10],
    ['x² on [−1, 2]', fn({ xRange: [-1, 2] }), (x) => x * x],
    ['x with θ4 = θ2', fn({ xRange: [0, 1], theta2RangeDeg: [0, 90], theta4RangeDeg: [0, 90] }), (x) => x],
  ];

  it.each(cases)('%s: a hint that really gives a linkage (checked by functionGenerator)', (_, s, f) => {
    const p = noLinkage(s, f);
    expect(p.hint).not.toBeNull();
    if (!p.hint) return;
    const t2 = p.hint.range === 'theta2' ? p.hint.deg : s.theta2RangeDeg;
    const t4 = p.hint.range === 'theta4' ? p.hint.deg : s.theta4RangeDeg;
    const r = functionGenerator({
      f,
      x: s.xRange,
      theta2: [rad(t2[0]), rad(t2[1])],
      theta4: [rad(t4[0]), rad(t4[1])],
      points: s.precisionPoints,
      samples: 201,
    });
    if (p.hint.clean) expect(r.defects).toEqual([]);
  });

  it('names the reason: the crank, the rocker, singular pairs', () => {
    expect(noLinkage(cases[0][1], cases[0][2]).reason).toBe('crank');
    expect(noLinkage(cases[1][1], cases[1][2]).reason).toBe('rocker');
    expect(noLinkage(cases[3][1], cases[3][2]).reason).toBe('singular');
  });

  it.each(cases)('%s: no long numbers, no nested parentheses, zh-TW fully translated', (_, s, f) => {
    const p = noLinkage(s, f);
    for (const fm of [functionMessagesEn, functionMessagesZhTw]) {
      const text = functionProblemText(fm, 'f', p);
      expect(text).not.toMatch(/\d{7,}|\d\.\d{6,}/);
      expect(text).not.toMatch(/[(（][^)）]*[(（]/);
    }
    const zh = functionProblemText(functionMessagesZhTw, 'f', p);
    // Only the symbols may be Latin: θ2, θ4, f, x.
    expect(zh).not.toMatch(/[A-Za-z]{2,}/);
    expect(zh).toContain('沒有實際的四連桿');
  });

  it('says where f turns back when it does (x² on [−1, 2] turns at 0)', () => {
    const p = noLinkage(cases[2][1], cases[2][2]);
    expect(p.turnsAt).not.toBeNull();
    expect(Math.abs(p.turnsAt as number)).toBeLessThanOrEqual(3 / 200);
    expect(functionProblemText(functionMessagesEn, 'x^2', p)).toMatch(/turns back near x = /);
  });
});
