import { CHART_STYLE } from './chartFrame';
import type { RateChartData, RateMarker } from './rateChart';
import type { Branch } from '../../solver/types';
import type { LinkRates } from '../../solver/rates';
import type { Direction, PlotLayout } from '../state/appState';
import type { Messages } from '../i18n/messages';
import type { PlotSeries, RateSeries } from '../solution';

/** The rate charts: ω3, ω4 or both; α3, α4 or both. */
export type RateChartKind = 'omega3' | 'omega4' | 'omegaBoth' | 'alpha3' | 'alpha4' | 'alphaBoth';

/** Both branches' rates on the plot samples, ω signed by the animation direction (rad/s, rad/s²). */
export interface CycleRates {
  theta2Deg: Float64Array;
  open: RateSeries | null;
  crossed: RateSeries | null;
}

/** Text and data of one rate chart, without its size or marker. */
export interface RateChartInputs {
  data: RateChartData;
  title: string;
  xLabel: string;
  yLabel: string;
}

const EMPTY = new Float64Array(0);

function negated(a: Float64Array): Float64Array {
  const out = new Float64Array(a.length);
  for (let i = 0; i < a.length; i++) out[i] = -a[i];
  return out;
}

/**
 * A plotted cycle's rates for the direction the input turns: they are solved for ω2 as set, and
 * reversing ω2 flips ω3 and ω4 and leaves α3 and α4 alone (they are even in ω2 for a fixed α2), so a
 * rocking input's reversal needs no new solve. Null when the plot has no rates.
 */
export function plotRates(plot: PlotSeries | null, direction: Direction): CycleRates | null {
  if (!plot) return null;
  const one = (b: typeof plot.open): RateSeries | null => {
    const r = b?.rates;
    if (!r) return null;
    return direction === 1 ? r : { ...r, omega3: negated(r.omega3), omega4: negated(r.omega4) };
  };
  const open = one(plot.open);
  const crossed = one(plot.crossed);
  if (!open && !crossed) return null;
  return { theta2Deg: plot.theta2Deg, open, crossed };
}

/** The rate charts of a plot kind in a layout: one for both links together, else one per link. */
export function rateChartKinds(kind: 'velocities' | 'accelerations', layout: PlotLayout): RateChartKind[] {
  if (kind === 'velocities') return layout === 'together' ? ['omegaBoth'] : ['omega3', 'omega4'];
  return layout === 'together' ? ['alphaBoth'] : ['alpha3', 'alpha4'];
}

function keysOf(kind: RateChartKind): (keyof LinkRates)[] {
  switch (kind) {
    case 'omega3':
      return ['omega3'];
    case 'omega4':
      return ['omega4'];
    case 'omegaBoth':
      return ['omega3', 'omega4'];
    case 'alpha3':
      return ['alpha3'];
    case 'alpha4':
      return ['alpha4'];
    case 'alphaBoth':
      return ['alpha3', 'alpha4'];
  }
}

const LABEL: Record<keyof LinkRates, string> = { omega3: 'ω3', omega4: 'ω4', alpha3: 'α3', alpha4: 'α4' };

/** Inputs of a rate chart: the branch's curves (the other branch faint when showOther) and labels. */
export function rateChartInputs(
  kind: RateChartKind,
  rates: CycleRates | null,
  branch: Branch,
  showOther: boolean,
  t: Messages,
): RateChartInputs {
  const cur = rates ? rates[branch] : null;
  const oth = rates ? rates[branch === 'open' ? 'crossed' : 'open'] : null;
  const series: RateChartData['series'] = [];
  for (const key of keysOf(kind)) {
    const color = key === 'omega3' || key === 'alpha3' ? CHART_STYLE.theta3 : CHART_STYLE.theta4;
    if (showOther) {
      series.push({
        label: `${LABEL[key]} (${t.legendOtherBranch})`,
        values: oth ? oth[key] : EMPTY,
        color,
        faint: true,
      });
    }
    series.push({ label: LABEL[key], values: cur ? cur[key] : EMPTY, color });
  }
  return {
    data: { theta2Deg: rates ? rates.theta2Deg : EMPTY, series },
    title: t.chartRates[kind],
    xLabel: t.axisTheta2,
    yLabel: kind.startsWith('omega') ? t.axisOmega : t.axisAlpha,
  };
}

/** The marker of a rate chart: theta2 (degrees) and this frame's rates in the order of the chart's solid series. */
export function rateMarker(kind: RateChartKind, theta2Deg: number, rates: LinkRates | null): RateMarker {
  return { theta2Deg, values: keysOf(kind).map((k) => (rates ? rates[k] : Number.NaN)) };
}
