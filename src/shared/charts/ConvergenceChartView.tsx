import { useCallback, useLayoutEffect, useRef, useState } from 'react';
import { createConvergenceChart } from './convergenceChart';
import type { ConvergenceChart } from './convergenceChart';
import type { ConvergenceInputs } from './chartInputs';
import { useElementSize } from '../hooks/useElementSize';

/** Props of ConvergenceChartView: the runs and labels; it sizes itself to its box. */
export interface ConvergenceChartViewProps {
  inputs: ConvergenceInputs;
  label: string;
}

/**
 * The live NR convergence chart (residual against iteration, log scale), created once per SVG element:
 * a new pose redraws the runs and the title (the axes only when their domain changes).
 */
export function ConvergenceChartView({ inputs, label }: ConvergenceChartViewProps) {
  const boxRef = useRef<HTMLDivElement>(null);
  const [chart, setChart] = useState<ConvergenceChart | null>(null);
  const svgRef = useCallback((svg: SVGSVGElement | null) => {
    setChart(svg ? createConvergenceChart(svg, 0, 0, { title: '', xLabel: '', yLabel: '' }) : null);
  }, []);
  const { width, height } = useElementSize(boxRef);
  const { runs, tolerance, title, xLabel, yLabel, toleranceLabel, emptyText } = inputs;

  useLayoutEffect(() => {
    chart?.setText({ title, xLabel, yLabel, emptyText });
  }, [chart, title, xLabel, yLabel, emptyText]);
  useLayoutEffect(() => {
    chart?.update({ runs, tolerance, toleranceLabel });
  }, [chart, runs, tolerance, toleranceLabel]);
  useLayoutEffect(() => {
    if (width > 0 && height > 0) chart?.resize(width, height);
  }, [chart, width, height]);

  return (
    <div className="chart-box" ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={label} className="chart-svg" />
    </div>
  );
}
