/**
 * y = f(x) from the text a student types, through math.js's parser (mathjs/number, the functions below only).
 *
 * Why math.js: it is the best-kept expression library on npm (15.x, releases every few weeks, a security page and
 * a history of fixed reports), it parses to a syntax tree and compiles that tree to closures: no eval, no
 * new Function, so a formula can never run JavaScript. Its own guards refuse property access to constructor,
 * __proto__ and the like; on top of them this module lets through only a whitelist of node kinds (numbers, x,
 * pi, e, + − * / ^, parentheses and the functions named in FUNCTIONS), so objects, strings, assignments,
 * accessors, matrices and blocks are refused before anything is compiled. The alternatives were smaller but
 * worse kept (expr-eval: unmaintained, with a code-injection advisory; jsep: a parser only, leaving evaluation to
 * us). The cost is measured in docs/synthesis.md: this module is its own chunk, loaded on first use of Function mode.
 */
import {
  absDependencies,
  acosDependencies,
  acoshDependencies,
  addDependencies,
  asinDependencies,
  asinhDependencies,
  atanDependencies,
  atanhDependencies,
  cbrtDependencies,
  compileDependencies,
  cosDependencies,
  coshDependencies,
  create,
  divideDependencies,
  eDependencies,
  expDependencies,
  expm1Dependencies,
  log10Dependencies,
  log1pDependencies,
  log2Dependencies,
  logDependencies,
  multiplyDependencies,
  parseDependencies,
  piDependencies,
  powDependencies,
  signDependencies,
  sinDependencies,
  sinhDependencies,
  sqrtDependencies,
  subtractDependencies,
  tanDependencies,
  tanhDependencies,
  unaryMinusDependencies,
  unaryPlusDependencies,
} from 'mathjs/number';
import type { MathNode } from 'mathjs';

/** A math.js instance with numbers only and just the operations a formula of x needs. */
const math = create({
  parseDependencies,
  compileDependencies,
  addDependencies,
  subtractDependencies,
  multiplyDependencies,
  divideDependencies,
  powDependencies,
  unaryMinusDependencies,
  unaryPlusDependencies,
  absDependencies,
  signDependencies,
  sqrtDependencies,
  cbrtDependencies,
  expDependencies,
  expm1Dependencies,
  logDependencies,
  log10Dependencies,
  log2Dependencies,
  log1pDependencies,
  sinDependencies,
  cosDependencies,
  tanDependencies,
  asinDependencies,
  acosDependencies,
  atanDependencies,
  sinhDependencies,
  coshDependencies,
  tanhDependencies,
  asinhDependencies,
  acoshDependencies,
  atanhDependencies,
  piDependencies,
  eDependencies,
});

/** Functions a formula may call, with the numbers of arguments each takes (log takes an optional base). */
export const FUNCTIONS: Readonly<Record<string, readonly number[]>> = {
  abs: [1],
  sign: [1],
  sqrt: [1],
  cbrt: [1],
  exp: [1],
  expm1: [1],
  log: [1, 2],
  log10: [1],
  log2: [1],
  log1p: [1],
  sin: [1],
  cos: [1],
  tan: [1],
  asin: [1],
  acos: [1],
  atan: [1],
  sinh: [1],
  cosh: [1],
  tanh: [1],
  asinh: [1],
  acosh: [1],
  atanh: [1],
};

/** Names a formula may use besides its functions: the variable and two constants. */
export const NAMES: readonly string[] = ['x', 'pi', 'e'];

/** Operators a formula may use (math.js's function names for + − * / ^ and the signs). */
const OPERATORS = new Set(['add', 'subtract', 'multiply', 'divide', 'pow', 'unaryMinus', 'unaryPlus']);

/** Why a text is not a formula of x: the page says it in words, naming the expression. */
export type ExpressionProblem =
  | { kind: 'syntax'; detail: string; char: number | null }
  | { kind: 'unknownName'; name: string }
  | { kind: 'unknownFunction'; name: string }
  | { kind: 'arguments'; name: string; count: number }
  | { kind: 'notAllowed'; what: Construct; detail?: string };

/** Constructs beyond arithmetic that a formula may not hold (the page names each in words). */
export type Construct =
  | 'access'
  | 'list'
  | 'assignment'
  | 'block'
  | 'condition'
  | 'definition'
  | 'index'
  | 'object'
  | 'range'
  | 'comparison'
  | 'text'
  | 'call'
  | 'operator'
  | 'other';

/** A parsed formula (f: x ↦ y, NaN where it has no real value) or why the text is not one. */
export type ParsedExpression = { ok: true; f: (x: number) => number } | { ok: false; problem: ExpressionProblem };

/** The construct each refused node kind is. */
const NODE_CONSTRUCTS: Record<string, Construct> = {
  AccessorNode: 'access',
  ArrayNode: 'list',
  AssignmentNode: 'assignment',
  BlockNode: 'block',
  ConditionalNode: 'condition',
  FunctionAssignmentNode: 'definition',
  IndexNode: 'index',
  ObjectNode: 'object',
  RangeNode: 'range',
  RelationalNode: 'comparison',
};

/** The first thing in the tree a formula may not hold, or null when every node is allowed. */
function firstProblem(node: MathNode): ExpressionProblem | null {
  switch (node.type) {
    case 'ConstantNode': {
      const value = (node as unknown as { value: unknown }).value;
      return typeof value === 'number' ? null : { kind: 'notAllowed', what: 'text' };
    }
    case 'SymbolNode': {
      const name = (node as unknown as { name: string }).name;
      return NAMES.includes(name) ? null : { kind: 'unknownName', name };
    }
    case 'ParenthesisNode':
      return firstProblem((node as unknown as { content: MathNode }).content);
    case 'OperatorNode': {
      const op = node as unknown as { fn: string; op: string; args: MathNode[] };
      if (!OPERATORS.has(op.fn)) return { kind: 'notAllowed', what: 'operator', detail: op.op };
      return childProblem(op.args);
    }
    case 'FunctionNode': {
      const call = node as unknown as { fn: MathNode; args: MathNode[] };
      if (call.fn.type !== 'SymbolNode') return { kind: 'notAllowed', what: 'call' };
      const name = (call.fn as unknown as { name: string }).name;
      const arities = Object.hasOwn(FUNCTIONS, name) ? FUNCTIONS[name] : null;
      if (!arities) return { kind: 'unknownFunction', name };
      if (!arities.includes(call.args.length)) return { kind: 'arguments', name, count: call.args.length };
      return childProblem(call.args);
    }
    default:
      return { kind: 'notAllowed', what: NODE_CONSTRUCTS[node.type] ?? 'other' };
  }
}

function childProblem(nodes: readonly MathNode[]): ExpressionProblem | null {
  for (const n of nodes) {
    const p = firstProblem(n);
    if (p) return p;
  }
  return null;
}

/**
 * The formula y = f(x) of text, or why it is not one: a syntax error (math.js's message), a name other than x,
 * pi and e, a function outside FUNCTIONS or with the wrong number of arguments, or any construct beyond
 * arithmetic (refused before compiling). f returns NaN where the formula has no real number value. Never throws.
 */
export function parseExpression(text: string): ParsedExpression {
  let node: MathNode;
  try {
    node = math.parse(text);
  } catch (e) {
    const detail = e instanceof Error ? e.message : String(e);
    // math.js ends its syntax errors with "(char N)", 1-based: kept apart so every language can say where.
    const at = /\(char (\d+)\)\s*$/.exec(detail);
    return { ok: false, problem: { kind: 'syntax', detail, char: at ? Number(at[1]) : null } };
  }
  const problem = firstProblem(node);
  if (problem) return { ok: false, problem };
  const compiled = node.compile();
  return {
    ok: true,
    f: (x: number) => {
      try {
        const y: unknown = compiled.evaluate({ x });
        return typeof y === 'number' ? y : Number.NaN;
      } catch {
        // math.js throws for a value outside a function's real domain in the number build (e.g. log of −1).
        return Number.NaN;
      }
    },
  };
}
