import { useMemo } from 'react';
import type { MarkerAt } from '../../shared/charts/chart';
import type { XYChartData } from '../../shared/charts/xyChart';
import { COLORS } from '../../shared/theme/tokens';
import { radToDeg } from '../../solver';
import type { SpatialPose } from '../../spatial';
import { XYChartView } from '../../shared/charts/XYChartView';
import { plotColumns } from './plotSeries';
import type { SpatialMessages } from './spatialMessages';
import type { SpatialAnalysis } from './useSpatialAnalysis';

/** Props of SpatialPlots: the analysis, θ2 and the pose there (the markers), the strings. */
export interface SpatialPlotsProps {
  analysis: SpatialAnalysis;
  theta2Deg: number;
  pose: SpatialPose | null;
  muRad: number | null;
  sm: SpatialMessages;
}

/** θ4, ω4, α4 and the transmission angle against θ2 over a turn, each with a marker at θ2. */
export function SpatialPlots({ analysis, theta2Deg, pose, muRad, sm }: SpatialPlotsProps) {
  const cols = useMemo(() => plotColumns(analysis.sweep), [analysis]);
  const data = useMemo(() => {
    const one = (label: string, color: string, y: Float64Array): XYChartData => ({
      series: [{ label, color, x: cols.theta2Deg, y }],
    });
    return {
      theta4: one('θ4', COLORS.rocker, cols.theta4Deg),
      omega4: one('ω4', COLORS.velocity, cols.omega4),
      alpha4: one('α4', COLORS.acceleration, cols.alpha4),
      mu: one('μ', COLORS.coupler, cols.muDeg),
    };
  }, [cols]);
  const marker = (y: number | null, color: string): MarkerAt => ({
    x: theta2Deg,
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
          fullTurn
          data={data[c.key]}
          marker={c.m}
          texts={{ title: c.title, xLabel: sm.axisTheta2, yLabel: c.y }}
          testId={`spatial-plot-${c.key}`}
        />
      ))}
    </div>
  );
}
