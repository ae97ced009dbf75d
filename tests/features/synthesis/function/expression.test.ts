import { afterEach, describe, expect, it } from 'vitest';
import { parseExpression } from '../../../../src/features/synthesis/function/expression';
import { expressionProblemText } from '../../../../src/features/synthesis/function/expressionText';
import { functionMessagesEn } from '../../../../src/features/synthesis/function/functionMessagesEn';
import { functionMessagesZhTw } from '../../../../src/features/synthesis/function/functionMessagesZhTw';

const g = globalThis as Record<string, unknown>;

describe('parseExpression', () => {
  afterEach(() => {
    delete g.__pwned;
  });

  it('evaluates formulas of x as Math does', () => {
    const cases: [string, (x: number) => number][] = [
      ['log10(x)', Math.log10],
      ['sin(x)^2 + cos(x)^2', () => 1],
      ['2 pi x', (x) => 2 * Math.PI * x],
      ['e^(-x/2) * sqrt(x)', (x) => Math.exp(-x / 2) * Math.sqrt(x)],
      ['log(x, 2) - log2(x)', () => 0],
      ['-x^2', (x) => -(x * x)],
      ['1/(1+x)', (x) => 1 / (1 + x)],
    ];
    for (const [text, ref] of cases) {
      const r = parseExpression(text);
      if (!r.ok) throw new Error(`${text}: ${JSON.stringify(r.problem)}`);
      for (const x of [0.5, 1, 2.75, 9]) expect(r.f(x), `${text} at ${x}`).toBeCloseTo(ref(x), 12);
    }
  });

  it('gives NaN where a formula has no real value, instead of throwing', () => {
    const r = parseExpression('sqrt(x) + log(x)');
    expect(r.ok && r.f(-1)).toBeNaN();
  });

  it.each([
    ['constructor.constructor("g.__pwned = 1")()', 'syntax'],
    ['constructor.constructor("globalThis.__pwned=1")', 'notAllowed'],
    ['x.__proto__', 'notAllowed'],
    ['x.constructor', 'notAllowed'],
    ['cos.constructor("globalThis.__pwned=1")', 'notAllowed'],
    ['f(x) = 1', 'notAllowed'],
    ['a = 1', 'notAllowed'],
    ['[x, 1]', 'notAllowed'],
    ['{a: 1}', 'notAllowed'],
    ['x; 1', 'notAllowed'],
    ['x ? 1 : 2', 'notAllowed'],
    ['x == 1', 'notAllowed'],
    ['"x"', 'notAllowed'],
    ['evaluate("1")', 'unknownFunction'],
    ['import({}, {})', 'unknownFunction'],
    ['constructor', 'unknownName'],
    ['y', 'unknownName'],
    ['sin(x, 2)', 'arguments'],
    ['log10(', 'syntax'],
  ])('refuses %s (%s) without evaluating it', (text, kind) => {
    const r = parseExpression(text);
    expect(r.ok).toBe(false);
    if (!r.ok) expect(r.problem.kind).toBe(kind);
    expect(g.__pwned).toBeUndefined();
  });

  it('names the construct it refuses: property access for x.__proto__, the operator for x!', () => {
    expect(parseExpression('x.__proto__')).toEqual({ ok: false, problem: { kind: 'notAllowed', what: 'access' } });
    expect(parseExpression('x!')).toEqual({
      ok: false,
      problem: { kind: 'notAllowed', what: 'operator', detail: '!' },
    });
  });
});

describe('expressionProblemText', () => {
  it('names the expression and says why, in both languages', () => {
    const bad = parseExpression('log10(');
    if (bad.ok) throw new Error('parsed');
    expect(expressionProblemText(functionMessagesEn, 'log10(', bad.problem)).toMatch(
      /^“log10\(” is not a formula of x: .*expected/i,
    );
    expect(expressionProblemText(functionMessagesZhTw, 'log10(', bad.problem)).toMatch(
      /^「log10\(」不是 x 的算式：第 7 個字元附近有語法錯誤/,
    );
    const unknown = parseExpression('foo(x)');
    if (unknown.ok) throw new Error('parsed');
    expect(expressionProblemText(functionMessagesEn, 'foo(x)', unknown.problem)).toMatch(
      /“foo” is not a function it knows \(abs, .*log10/,
    );
    expect(expressionProblemText(functionMessagesEn, 'x[0]', { code: 'character', character: '[' })).toMatch(
      /^“x\[0\]” is not a formula of x: “\[” cannot appear/,
    );
  });
});
