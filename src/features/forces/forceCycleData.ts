import type { SweepForces } from '../../solver/forces';
import { forceCycle } from '../../solver/forcesCycle';
import type { ForceCycleStatus, TorqueCycleStats } from '../../solver/forcesCycle';
import type { Branch } from '../../solver/types';
import type { ForceSetup } from './forceModel';

/** Magnitudes of the four pin forces over a sweep (N), NaN where undetermined. */
export interface PinMagnitudes {
  f12: Float64Array;
  f32: Float64Array;
  f43: Float64Array;
  f14: Float64Array;
}

/** One crank turn of forces for the plots and cycle numbers: θ2 in degrees, the forces (SI) and their statistics. */
export interface CycleForcesView {
  status: ForceCycleStatus;
  theta2Deg: Float64Array;
  forces: SweepForces;
  magnitudes: PinMagnitudes;
  stats: TorqueCycleStats;
  /** A typical pin-force magnitude over the turn (N): the 90th percentile of all four, the canvas arrows' scale. */
  typicalPinForce: number;
}

/** |F| of each pin force at every sample. */
export function pinMagnitudes(f: SweepForces): PinMagnitudes {
  const n = f.torque.length;
  const out = {
    f12: new Float64Array(n),
    f32: new Float64Array(n),
    f43: new Float64Array(n),
    f14: new Float64Array(n),
  };
  for (let i = 0; i < n; i++) {
    out.f12[i] = Math.hypot(f.f12x[i], f.f12y[i]);
    out.f32[i] = Math.hypot(f.f32x[i], f.f32y[i]);
    out.f43[i] = Math.hypot(f.f43x[i], f.f43y[i]);
    out.f14[i] = Math.hypot(f.f14x[i], f.f14y[i]);
  }
  return out;
}

/** The 90th percentile of the finite pin-force magnitudes (NaN without any): near a toggle a few samples run away. */
function typicalOf(m: PinMagnitudes): number {
  const all: number[] = [];
  for (const a of [m.f12, m.f32, m.f43, m.f14]) for (const v of a) if (Number.isFinite(v)) all.push(v);
  if (all.length === 0) return Number.NaN;
  all.sort((a, b) => a - b);
  return all[Math.min(all.length - 1, Math.floor(0.9 * all.length))];
}

/**
 * One turn of the crank (samples intervals, θ2 = 0 to 360° inclusive) on a branch, solved by the closed form, with
 * the forces, the pin-force magnitudes and the torque's cycle statistics (solver forceCycle: NaN statistics and a
 * status when the crank cannot turn fully or passes a limit position). Null if the solver refuses the setup.
 */
export function cycleForces(setup: ForceSetup, branch: Branch, samples: number): CycleForcesView | null {
  let c: ReturnType<typeof forceCycle>;
  try {
    c = forceCycle(setup.linkage, branch, setup.input, setup.inertia, setup.loads, { points: samples, k: setup.k });
  } catch {
    return null;
  }
  const theta2Deg = new Float64Array(c.theta2.length);
  for (let i = 0; i < theta2Deg.length; i++) theta2Deg[i] = (360 * i) / samples;
  const magnitudes = pinMagnitudes(c.forces);
  return {
    status: c.status,
    theta2Deg,
    forces: c.forces,
    magnitudes,
    stats: c.stats,
    typicalPinForce: typicalOf(magnitudes),
  };
}
