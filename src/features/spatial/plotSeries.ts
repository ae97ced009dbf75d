import { TWO_PI, radToDeg } from '../../solver';
import type { InputRange } from '../../solver';
import type { SpatialSweep } from '../../spatial';

/**
 * Where the plots' θ2 axis starts and ends, radians: a full turn from 0 for a crank; for an input that rocks, its
 * reachable range from the first interval's lower end (so a range through 0, −98° … 98°, is one piece), up to the last
 * interval's upper end; [0, 2π] when nothing is reachable.
 */
export function plotSpan(range: InputRange): { lo: number; hi: number } {
  if (range.full || !range.intervals.length) return { lo: 0, hi: TWO_PI };
  const lo = range.intervals[0].lo;
  let hi = lo;
  for (const iv of range.intervals) hi = Math.max(hi, lo + wrapTwoPi(iv.hi - lo));
  return { lo, hi };
}

/** x in [0, 2π) (a full turn's end stays 2π when it is one). */
function wrapTwoPi(x: number): number {
  const r = x - TWO_PI * Math.floor(x / TWO_PI);
  return r === 0 && x > 0 ? TWO_PI : r;
}

/** θ2 (degrees, any turn) on the plots' axis: in [lo, lo + 360) for the span's lower end lo (degrees). */
export function plotTheta2Deg(theta2Deg: number, loDeg: number): number {
  return loDeg + ((((theta2Deg - loDeg) % 360) + 360) % 360);
}

/** The plots' columns of a sweep: θ2 and θ4 in degrees (θ4 broken where it wraps), ω4, α4, μ in degrees. */
export interface SpatialPlotColumns {
  theta2Deg: Float64Array;
  theta4Deg: Float64Array;
  omega4: Float64Array;
  alpha4: Float64Array;
  muDeg: Float64Array;
}

/** Largest jump of θ4 between samples that is drawn as a line (a wrap through ±180° is a gap), degrees. */
const WRAP_GAP_DEG = 180;

/**
 * The sweep's columns for the plots: not-closing samples are NaN (gaps), θ4 gets a gap where it wraps, and
 * unbounded rates at a limit (±Infinity) are gaps too.
 */
export function plotColumns(sweep: SpatialSweep): SpatialPlotColumns {
  const n = sweep.theta2.length;
  const out: SpatialPlotColumns = {
    theta2Deg: new Float64Array(n),
    theta4Deg: new Float64Array(n),
    omega4: new Float64Array(n),
    alpha4: new Float64Array(n),
    muDeg: new Float64Array(n),
  };
  let prev = NaN;
  for (let i = 0; i < n; i++) {
    out.theta2Deg[i] = radToDeg(sweep.theta2[i]);
    const ok = sweep.valid[i] === 1;
    const t4 = ok ? radToDeg(sweep.theta4[i]) : NaN;
    // A wrap: end the line at this sample by a gap (NaN) rather than a vertical stroke across the plot.
    out.theta4Deg[i] = Math.abs(t4 - prev) > WRAP_GAP_DEG ? NaN : t4;
    prev = t4;
    out.omega4[i] = ok && Number.isFinite(sweep.omega4[i]) ? sweep.omega4[i] : NaN;
    out.alpha4[i] = ok && Number.isFinite(sweep.alpha4[i]) ? sweep.alpha4[i] : NaN;
    out.muDeg[i] = ok ? radToDeg(sweep.mu[i]) : NaN;
  }
  return out;
}
