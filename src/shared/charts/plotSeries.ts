// The solver's modules one by one: the main thread draws the plots with this, and the barrel would pull the
// whole solver into the main bundle.
import { radToDeg } from '../../solver/angles';
import type { InputMotion } from '../../solver/rates';
import { sweepRates } from '../../solver/rates';
import { adaptiveGrid } from '../../solver/sampling';
import { sweep } from '../../solver/sweep';
import type { Branch, Linkage } from '../../solver/types';
import type { MethodChoice, PlotSeries } from '../solution';

/** Sweep options for a method choice: an explicit tolerance turns polishing off, so the tolerance shows. */
export function sweepOptions(branch: Branch, solver: MethodChoice) {
  return { branch, method: solver.method, tol: solver.tol ?? undefined, polish: solver.tol === null };
}

/**
 * The plotted cycle at pixel resolution: the branches asked for, solved with the chosen method on an adaptive grid
 * of about `pixels` samples (denser near the input's limits), with the link rates when `rates` gives the input
 * motion. A few hundred points: the main thread solves it in the frame of an edit (about 1 ms at 600 pixels).
 */
export function plotSeries(
  l: Linkage,
  pixels: number,
  branches: readonly Branch[],
  solver: MethodChoice,
  rates: InputMotion | null,
): PlotSeries {
  const grid = adaptiveGrid(l, { pixels, branches: [...branches] });
  const one = (b: Branch) => {
    if (!branches.includes(b)) return null;
    const r = sweep(l, grid, sweepOptions(b, solver));
    if (!rates) return { theta3: r.theta3, theta4: r.theta4 };
    const w = sweepRates(l, grid, r.theta3, r.theta4, (i) => r.status[i] === 'ok', rates);
    return { theta3: r.theta3, theta4: r.theta4, rates: w };
  };
  return { theta2Deg: grid.map(radToDeg), open: one('open'), crossed: one('crossed') };
}
