import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE, reducer } from '../../../../src/shared/state/appState';
import {
  DEFAULT_SYN_FUNCTION,
  expressionTextProblem,
  rangeProblem,
} from '../../../../src/shared/state/slices/synFunctionSlice';
import { parseUrl, serializeState } from '../../../../src/shared/url/url';

const quiet = () => {};

describe('synFunctionReducer', () => {
  it('starts from log10 on [1, 10], θ2 30° to 90°, θ4 −60° to −150°, three points', () => {
    expect(DEFAULT_STATE.synFunction).toEqual({
      expression: 'log10(x)',
      xRange: [1, 10],
      theta2RangeDeg: [30, 90],
      theta4RangeDeg: [-60, -150],
      precisionPoints: 3,
    });
  });

  it('patches fields and returns the same state when nothing changes', () => {
    const s = reducer(DEFAULT_STATE, { type: 'setSynFunction', patch: { expression: 'sin(x)', precisionPoints: 5 } });
    expect(s.synFunction).toMatchObject({ expression: 'sin(x)', precisionPoints: 5, xRange: [1, 10] });
    expect(reducer(DEFAULT_STATE, { type: 'setSynFunction', patch: { xRange: [1, 10] } })).toBe(DEFAULT_STATE);
  });
});

describe('Function URL keys', () => {
  it('writes nothing for the defaults and reads back every key it writes', () => {
    expect(serializeState(DEFAULT_STATE)).not.toMatch(/(^|&)(fx|xr|t2r|t4r|np)=/);
    const s = {
      ...DEFAULT_STATE,
      synFunction: {
        expression: 'x^2 + 2*x - 1/(x+3)',
        xRange: [-2.5, 4] as [number, number],
        theta2RangeDeg: [-45, 120.5] as [number, number],
        theta4RangeDeg: [200, 100] as [number, number],
        precisionPoints: 7,
      },
    };
    const text = serializeState(s);
    for (const k of ['fx', 'xr', 't2r', 't4r', 'np']) expect(new URLSearchParams(text).has(k), k).toBe(true);
    const back = parseUrl(text, DEFAULT_STATE, quiet);
    expect(back.ignored).toEqual([]);
    expect(back.state.synFunction).toEqual(s.synFunction);
  });

  it.each([
    ['fx', '', /empty/],
    ['fx', 'constructor.constructor("alert(1)")()', /may use only letters.*not "\\""/],
    ['fx', 'x; 1', /not ";"/],
    ['fx', 'x = 1', /not "="/],
    ['fx', 'x'.repeat(201), /longer than 200/],
    ['xr', '1', /2 comma-separated numbers, got 1/],
    ['xr', '2,2', /ends must differ/],
    ['xr', '1,abc', /"abc" is not a number/],
    ['xr', '0,1e13', /within ±1000000000000/],
    ['t2r', '0,400', /within ±360/],
    ['t2r', '-300,300', /span at most 360°/],
    ['t4r', '10,10', /ends must differ/],
    ['np', '2', /whole number from 3 to 50/],
    ['np', '51', /whole number from 3 to 50/],
    ['np', '3.5', /whole number from 3 to 50/],
  ])('refuses %s=%s, saying why, and keeps the default', (key, value, why) => {
    const r = parseUrl(`${key}=${encodeURIComponent(value)}`, DEFAULT_STATE, quiet);
    expect(r.ignored.map((p) => p.key)).toEqual([key]);
    expect(r.ignored[0].why).toMatch(why);
    expect(r.state.synFunction).toEqual(DEFAULT_SYN_FUNCTION);
  });
});

describe('expressionTextProblem', () => {
  it('lets arithmetic through and names the first character a formula cannot hold', () => {
    expect(expressionTextProblem(' log10(x) + 2^x * sin(pi/4) ')).toBeNull();
    expect(expressionTextProblem('x.__proto__')).toBeNull();
    expect(expressionTextProblem('a[0]')).toEqual({ code: 'character', character: '[' });
    expect(expressionTextProblem('`x`')).toEqual({ code: 'character', character: '`' });
    expect(expressionTextProblem('   ')).toEqual({ code: 'empty' });
  });
});

describe('rangeProblem', () => {
  it('asks for distinct finite ends within the limit and at most a turn of angle', () => {
    expect(rangeProblem([1, 10], 'x')).toBeNull();
    expect(rangeProblem([1, 1], 'x')).toBe('ends');
    expect(rangeProblem([Number.NaN, 1], 'x')).toBe('finite');
    expect(rangeProblem([-180, 180], 'angle')).toBeNull();
    expect(rangeProblem([-200, 180], 'angle')).toBe('span');
    expect(rangeProblem([0, 361], 'angle')).toBe('within');
  });
});
