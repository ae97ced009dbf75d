import { useCallback } from 'react';
import { drawConvergenceChart } from '../charts/convergenceChart';
import type { ConvergenceInputs } from './chartInputs';
import { SvgChartView } from './SvgChartView';

/** Props of ConvergenceChartView: the runs and labels; it sizes itself to its box. */
export interface ConvergenceChartViewProps {
  inputs: ConvergenceInputs;
  label: string;
}

/** The live NR convergence chart (residual against iteration, log scale). */
export function ConvergenceChartView({ inputs, label }: ConvergenceChartViewProps) {
  const draw = useCallback(
    (svg: SVGSVGElement, width: number, height: number) => {
      const { runs, ...opts } = inputs;
      drawConvergenceChart(svg, runs, { ...opts, width, height });
    },
    [inputs],
  );
  return <SvgChartView draw={draw} label={label} />;
}
