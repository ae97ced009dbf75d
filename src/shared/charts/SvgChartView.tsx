import './SvgChartView.css';
import { useLayoutEffect, useRef } from 'react';
import { useElementSize } from '../hooks/useElementSize';

/** Props of SvgChartView: a draw function called with the SVG and its size in CSS pixels. */
export interface SvgChartViewProps {
  draw: (svg: SVGSVGElement, width: number, height: number) => void;
  label: string;
  className?: string;
  testId?: string;
}

/** An SVG chart that fills its box and redraws when draw or the box size changes. */
export function SvgChartView({ draw, label, className, testId }: SvgChartViewProps) {
  const boxRef = useRef<HTMLDivElement>(null);
  const svgRef = useRef<SVGSVGElement>(null);
  const { width, height } = useElementSize(boxRef);
  useLayoutEffect(() => {
    const svg = svgRef.current;
    if (!svg || width <= 0 || height <= 0) return;
    draw(svg, width, height);
  }, [draw, width, height]);
  return (
    <div className={className ? `chart-box ${className}` : 'chart-box'} ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={label} className="chart-svg" data-testid={testId} />
    </div>
  );
}
