import { useLayoutEffect, useRef } from 'react';
import { drawConvergenceChart } from '../charts/convergenceChart';
import type { ConvergenceInputs } from './chartInputs';
import { useElementSize } from './useElementSize';

/** Props of ConvergenceChartView: the runs and labels; it sizes itself to its box. */
export interface ConvergenceChartViewProps {
  inputs: ConvergenceInputs;
  label: string;
}

/** The live NR convergence chart (residual against iteration, log scale). */
export function ConvergenceChartView({ inputs, label }: ConvergenceChartViewProps) {
  const boxRef = useRef<HTMLDivElement>(null);
  const svgRef = useRef<SVGSVGElement>(null);
  const { width, height } = useElementSize(boxRef);

  useLayoutEffect(() => {
    const svg = svgRef.current;
    if (!svg || width <= 0 || height <= 0) return;
    const { runs, ...opts } = inputs;
    drawConvergenceChart(svg, runs, { ...opts, width, height });
  }, [inputs, width, height]);

  return (
    <div className="chart-box" ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={label} className="chart-svg" />
    </div>
  );
}
