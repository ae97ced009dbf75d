import { useMemo } from 'react';
import type { MarkerAt } from '../../shared/charts/chart';
import type { XYChartData } from '../../shared/charts/xyChart';
import { COLORS } from '../../shared/theme/tokens';
import { radToDeg } from '../../solver';
import { XYChartView } from '../../shared/charts/XYChartView';
import { plotColumns, plotTheta2Deg } from './plotSeries';
import type { SpatialMessages } from './spatialMessages';
import type { SpatialFrame, SpatialPlayhead } from './spatialPlayhead';
import { useShownFrame } from './spatialPlayhead';
import type { SpatialAnalysis } from './useSpatialAnalysis';

/** Props of SpatialPlots: the analysis, the frame of the state (base) and Play's playhead ahead of it (the markers), the strings. */
export interface SpatialPlotsProps {
  analysis: SpatialAnalysis;
  playhead: SpatialPlayhead;
  base: SpatialFrame;
  sm: SpatialMessages;
}

/** θ4, ω4, α4 and the transmission angle against θ2 over a turn, each with a marker at θ2. */
export function SpatialPlots({ analysis, playhead, base, sm }: SpatialPlotsProps) {
  const { pose, muRad, theta2Deg } = useShownFrame(playhead, base);
  const cols = useMemo(() => plotColumns(analysis.sweep), [analysis]);
  const loDeg = radToDeg(analysis.span.lo);
  const hiDeg = radToDeg(analysis.span.hi);
  const data = useMemo(() => {
    // The x axis is the input's reachable range: a full turn only when the input turns fully.
    const xDomain: [number, number] = [loDeg, hiDeg];
    const one = (label: string, color: string, y: Float64Array): XYChartData => ({
      series: [{ label, color, x: cols.theta2Deg, y }],
      xDomain,
    });
    return {
      theta4: one('θ4', COLORS.rocker, cols.theta4Deg),
      omega4: one('ω4', COLORS.velocity, cols.omega4),
      alpha4: one('α4', COLORS.acceleration, cols.alpha4),
      mu: one('μ', COLORS.coupler, cols.muDeg),
    };
  }, [cols, loDeg, hiDeg]);
  const marker = (y: number | null, color: string): MarkerAt => ({
    x: plotTheta2Deg(theta2Deg, loDeg),
    dots: y === null || !Number.isFinite(y) ? [] : [{ y, color }],
  });
  const charts = [
    {
      key: 'theta4',
      title: sm.plotTheta4,
      y: 'θ4 (°)',
      m: marker(pose ? radToDeg(pose.theta4) : null, COLORS.rocker),
    },
    { key: 'omega4', title: sm.plotOmega4, y: 'ω4 (rad/s)', m: marker(pose?.omega4 ?? null, COLORS.velocity) },
    { key: 'alpha4', title: sm.plotAlpha4, y: 'α4 (rad/s²)', m: marker(pose?.alpha4 ?? null, COLORS.acceleration) },
    { key: 'mu', title: sm.plotMu, y: 'μ (°)', m: marker(muRad === null ? null : radToDeg(muRad), COLORS.coupler) },
  ] as const;
  return (
    <div className="spatial-plots">
      {charts.map((c) => (
        <XYChartView
          key={c.key}
          className="spatial-chart"
          data={data[c.key]}
          marker={c.m}
          texts={{ title: c.title, xLabel: sm.axisTheta2, yLabel: c.y }}
          testId={`spatial-plot-${c.key}`}
        />
      ))}
    </div>
  );
}
