import { useMemo } from 'react';
import type { SynFunctionState } from '../../../shared/state/slices/synFunctionSlice';
import type { XYChartData } from '../../../shared/charts/xyChart';
import { COLORS } from '../../../shared/theme/tokens';
import type { FunctionMessages } from './functionMessages';
import type { ExpressionParser } from './useExpressionParser';
import type { FunctionDesign } from './functionSolve';
import { solveFunction } from './functionSolve';
import { expressionProblemText, functionProblemText } from './expressionText';

/** What the Function mode shows for its settings: the design (null without one), f, and the problem in words. */
export interface FunctionDesignState {
  fd: FunctionDesign | null;
  /** The parsed function, or null while the expression does not parse. */
  f: ((x: number) => number) | null;
  /** Why there is no design (the expression or the solve), in words; null where there is one or no parser. */
  problem: string | null;
}

/** The expression parsed and the function generator solved for the settings (each memoised on its inputs). */
export function useFunctionDesign(
  s: SynFunctionState,
  parse: ExpressionParser,
  fm: FunctionMessages,
): FunctionDesignState {
  const parsed = useMemo(() => (parse ? parse(s.expression) : null), [parse, s.expression]);
  const outcome = useMemo(() => (parsed?.ok ? solveFunction(s, parsed.f) : null), [parsed, s]);
  const fd = outcome?.ok ? outcome.value : null;
  const problem = !parsed
    ? null
    : !parsed.ok
      ? expressionProblemText(fm, s.expression, parsed.problem)
      : outcome && !outcome.ok
        ? functionProblemText(fm, s.expression, outcome.problem)
        : null;
  return { fd, f: parsed?.ok ? parsed.f : null, problem };
}

/** The structural error chart's series: the error against x, and the precision points as dots. */
export function structuralErrorData(fd: FunctionDesign | null, fm: FunctionMessages): XYChartData {
  if (!fd) return { series: [] };
  return {
    series: [
      {
        label: fm.errorSeries,
        color: COLORS.residual,
        x: fd.result.structuralError.map((e) => e.x),
        y: fd.result.structuralError.map((e) => e.error),
      },
      {
        label: fm.precisionSeries,
        color: COLORS.marker,
        x: fd.precision.map((p) => p.x),
        y: fd.precision.map((p) => p.error),
        line: false,
        dots: true,
      },
    ],
  };
}
