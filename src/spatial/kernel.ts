import type { InputRange } from '../solver';
import { rssrInputRange, sphericalInputRange } from './classify';
import type { Closure, SpatialPoint } from './point';
import { planRSSR, rssrAt, rssrRates } from './rssr';
import { couplerPointOf, planSpherical, sphericalAt, sphericalRates } from './spherical';
import type { SpatialModel, Vec3 } from './types';
import { describe } from './validate';

/** One planned linkage behind a common face, so sweeps, exports and the output's motion serve both kinds. */
export interface Kernel {
  at(theta2: number, sigma: number, p: SpatialPoint): Closure;
  rates(p: SpatialPoint, omega2: number, alpha2: number): void;
  /** The user's length unit per working unit (1 on the unit sphere). */
  unit: number;
  /** The coupler point's construction (spherical with pDist), else null. */
  coupler: ((A: Vec3, B: Vec3) => Vec3) | null;
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
      coupler: plan.hasP ? (A, B) => couplerPointOf(plan, A, B) : null,
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
