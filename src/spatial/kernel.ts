import type { InputRange } from '../solver';
import { rssrInputRange, sphericalInputRange } from './classify';
import type { Closure, SpatialPoint } from './point';
import { planRSSR, rssrAt, rssrRates } from './rssr';
import { couplerPointInto, planSpherical, sphericalAt, sphericalRates } from './spherical';
import type { SpatialModel } from './types';
import { describe } from './validate';

/** One planned linkage behind a common face, so sweeps, exports and the output's motion serve both kinds. */
export interface Kernel {
  at(theta2: number, sigma: number, p: SpatialPoint): Closure;
  rates(p: SpatialPoint, omega2: number, alpha2: number): void;
  /** The user's length unit per working unit (1 on the unit sphere). */
  unit: number;
  /** Writes the coupler point of a solved point to out[at..at+2] (spherical with pDist), else null. */
  coupler: ((p: SpatialPoint, out: Float64Array | number[], at: number) => void) | null;
  inputRange(): InputRange;
}

/** The kernel of a model; throws an Error naming the field for a bad linkage or kind. */
export function kernelOf(model: SpatialModel): Kernel {
  if (model?.kind === 'spherical') {
    const plan = planSpherical(model.linkage);
    return {
      at: (t, s, p) => sphericalAt(plan, t, s, p),
      rates: (p, w, a) => sphericalRates(plan, p, w, a),
      unit: 1,
      coupler: plan.hasP ? (p, out, at) => couplerPointInto(plan, p.ax, p.ay, p.az, p.bx, p.by, p.bz, out, at) : null,
      inputRange: () => sphericalInputRange(model.linkage),
    };
  }
  if (model?.kind === 'rssr') {
    const plan = planRSSR(model.linkage);
    return {
      at: (t, s, p) => rssrAt(plan, t, s, p),
      rates: (p, w, a) => rssrRates(plan, p, w, a),
      unit: plan.unit,
      coupler: null,
      inputRange: () => rssrInputRange(model.linkage),
    };
  }
  throw new Error(`model.kind must be 'spherical' or 'rssr', got ${describe((model as { kind?: unknown })?.kind)}`);
}
