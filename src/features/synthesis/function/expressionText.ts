import type { ExpressionTextProblem } from '../../../shared/state/slices/synFunctionSlice';
import { MAX_EXPRESSION_CHARS } from '../../../shared/state/slices/synFunctionSlice';
import { formatNumber } from '../../../shared/format';
import type { ExpressionProblem } from './expression';
import type { FunctionMessages } from './functionMessages';
import type { FunctionProblem } from './functionSolve';

/** Functions a formula may call, listed for messages (as expression.ts's FUNCTIONS, without loading the parser). */
export const FUNCTION_NAMES =
  'abs, sign, sqrt, cbrt, exp, expm1, log, log10, log2, log1p, sin, cos, tan, asin, acos, atan, sinh, cosh, tanh, asinh, acosh, atanh';

/** Why a text is not a formula, in words, naming the expression. */
export function expressionProblemText(
  fm: FunctionMessages,
  expression: string,
  p: ExpressionProblem | ExpressionTextProblem,
): string {
  const why = (() => {
    if ('code' in p) {
      if (p.code === 'empty') return fm.why.empty;
      if (p.code === 'long') return fm.why.long(MAX_EXPRESSION_CHARS);
      return fm.why.character(p.character);
    }
    switch (p.kind) {
      case 'syntax':
        return fm.why.syntax(p.detail, p.char);
      case 'unknownName':
        return fm.why.unknownName(p.name);
      case 'unknownFunction':
        return fm.why.unknownFunction(p.name, FUNCTION_NAMES);
      case 'arguments':
        return fm.why.arguments(p.name, p.count);
      case 'notAllowed':
        return fm.why.notAllowed(p.detail ? `${fm.constructs[p.what]} ${p.detail}` : fm.constructs[p.what]);
    }
  })();
  return fm.expressionProblem(expression, why);
}

/** Why there is no function generator, in words, naming the expression. */
export function functionProblemText(fm: FunctionMessages, expression: string, p: FunctionProblem): string {
  if (p.code === 'notFinite') return fm.notFinite(expression, formatNumber(p.x, 6));
  if (p.code === 'sameEnds') return fm.sameEnds(expression, formatNumber(p.y, 6));
  const turns = p.turnsAt === null ? '' : fm.noLinkageTurns(formatNumber(p.turnsAt, 4));
  const hint = p.hint
    ? fm.noLinkageHint(
        p.hint.range === 'theta2' ? 'θ2' : 'θ4',
        formatNumber(p.hint.deg[0], 6),
        formatNumber(p.hint.deg[1], 6),
        p.hint.clean,
      )
    : fm.noLinkageNoHint;
  return fm.noLinkage(fm.noLinkageWhy[p.reason], turns, hint);
}
