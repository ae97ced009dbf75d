import { tickIncrement, tickStep, ticks as linearTicks } from 'd3-array';

/**
 * The simulator's chart scales: linear and log maps from data to pixels, with d3-scale's behaviour for what the
 * charts use (a map, its inverse, domain, range, copy, ticks and tick format). d3-array gives the ticks and nice
 * domains; d3-axis draws the axes from these scales. d3-scale itself would bring d3-interpolate, d3-color and
 * d3-format onto the first load (about 7.5 KB gzip, issue 11) for a linear map; the lab's charts, loaded on
 * demand, still use it.
 */

/** A continuous scale from data to pixels: what d3-axis and the charts call on a scale. */
export interface Scale {
  (value: number): number;
  /** The data value at a pixel position. */
  invert(px: number): number;
  domain(): [number, number];
  range(): [number, number];
  /** An independent scale with the same domain and range (d3-axis keeps one to place ticks). */
  copy(): Scale;
}

/** A linear scale: what the angle, rate and transmission charts and the convergence chart's x axis use. */
export interface LinearScale extends Scale {
  copy(): LinearScale;
  /** About count round ticks in the domain (d3-array's ticks). */
  ticks(count: number): number[];
  /** d3-scale's default linear tick format for about count ticks: fixed decimals of the tick step, thousands grouped. */
  tickFormat(count: number): (value: number) => string;
}

/**
 * [lo, hi] (lo <= hi) widened to round values for about count ticks: d3-scale's linear nice, step for step (at most
 * ten rounds of d3-array's tickIncrement; the domain unchanged when the step does not settle).
 */
export function niceLinearDomain(lo: number, hi: number, count: number): [number, number] {
  let start = lo;
  let stop = hi;
  let prestep: number | undefined;
  for (let round = 0; round < 10; round++) {
    const step = tickIncrement(start, stop, count);
    if (step === prestep) return [start, stop];
    if (step > 0) {
      start = Math.floor(start / step) * step;
      stop = Math.ceil(stop / step) * step;
    } else if (step < 0) {
      start = Math.ceil(start * step) / step;
      stop = Math.floor(stop * step) / step;
    } else break;
    prestep = step;
  }
  return [lo, hi];
}

function interpolate(r: [number, number], t: number): number {
  return r[0] * (1 - t) + r[1] * t;
}

/** A linear map from domain to range; values outside the domain extrapolate, as in d3. */
export function linearScale(domain: readonly [number, number], range: readonly [number, number]): LinearScale {
  const d: [number, number] = [domain[0], domain[1]];
  const r: [number, number] = [range[0], range[1]];
  const span = d[1] - d[0];
  const scale = ((v: number) => interpolate(r, span === 0 ? 0.5 : (v - d[0]) / span)) as LinearScale;
  scale.invert = (px) => {
    const rs = r[1] - r[0];
    return interpolate(d, rs === 0 ? 0.5 : (px - r[0]) / rs);
  };
  scale.domain = () => [d[0], d[1]];
  scale.range = () => [r[0], r[1]];
  scale.copy = () => linearScale(d, r);
  scale.ticks = (count) => linearTicks(d[0], d[1], count);
  scale.tickFormat = (count) => {
    const step = Math.abs(tickStep(d[0], d[1], count));
    const decimals = step > 0 && Number.isFinite(step) ? Math.max(0, -Math.floor(Math.log10(step))) : 0;
    const f = new Intl.NumberFormat('en-US', { minimumFractionDigits: decimals, maximumFractionDigits: decimals });
    // As d3-format: no sign on a value that rounds to zero.
    return (v) => f.format(v).replace(/^-(?=[0.,]*$)/, '');
  };
  return scale;
}

/**
 * A base-10 log map from a positive domain to range, clamped like d3's `scaleLog().clamp(true)`: values below the
 * domain (zero among them) go to its lower end, values above it to its upper end.
 */
export function logScale(domain: readonly [number, number], range: readonly [number, number]): Scale {
  const d: [number, number] = [domain[0], domain[1]];
  const r: [number, number] = [range[0], range[1]];
  const l0 = Math.log10(d[0]);
  const span = Math.log10(d[1]) - l0;
  const clampT = (t: number) => Math.min(1, Math.max(0, t));
  const scale = ((v: number) => {
    const t = v > 0 ? (Math.log10(v) - l0) / span : d[0] < d[1] ? 0 : 1;
    return interpolate(r, span === 0 ? 0.5 : clampT(t));
  }) as Scale;
  scale.invert = (px) => {
    const rs = r[1] - r[0];
    return 10 ** (l0 + span * clampT(rs === 0 ? 0.5 : (px - r[0]) / rs));
  };
  scale.domain = () => [d[0], d[1]];
  scale.range = () => [r[0], r[1]];
  scale.copy = () => logScale(d, r);
  return scale;
}
