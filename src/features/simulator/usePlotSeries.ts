import { useMemo } from 'react';
import type { InputMotion } from '../../solver/rates';
import type { Branch, Linkage } from '../../solver/types';
import { plotSeries } from '../../shared/charts/plotSeries';
import type { MethodChoice, PlotSeries } from '../../shared/solution';

/** What the visible plots need: their pixel width, the branches drawn, the method, the rates' input motion. */
export interface PlotNeeds {
  /** Device-pixel width of the visible plots; 0 when none shows (nothing is solved). */
  plotPixels: number;
  branch: Branch;
  /** The other branch is drawn too (faint lines). */
  otherBranch: boolean;
  solver: MethodChoice;
  /** Input motion of a visible rate plot (rad/s, rad/s²); null when no rate plot shows. */
  rates: InputMotion | null;
}

/** A plotted cycle and the lengths it was solved for. */
export interface SolvedPlot {
  linkage: Linkage;
  plot: PlotSeries;
}

/**
 * The plotted cycle for these lengths, solved on the main thread in the render that changes them (plotSeries, about
 * 1 ms at 600 pixels): a dragged length redraws the plots in the frame of the input, without a worker round trip.
 * The worker keeps the cycle's NR statistics, the coupler curves and the tables. Null when no plot shows or the
 * lengths cannot be solved (the cycle's error says why).
 */
export function usePlotSeries(linkage: Linkage, needs: PlotNeeds): SolvedPlot | null {
  const { r1, r2, r3, r4 } = linkage;
  const { plotPixels, rates } = needs;
  // With both branches drawn the branch choice does not change the solve: no re-solve on a branch switch.
  const only: Branch | null = needs.otherBranch ? null : needs.branch;
  const { method, tol } = needs.solver;
  const omega2 = rates ? rates.omega2 : null;
  const alpha2 = rates ? rates.alpha2 : null;
  return useMemo(() => {
    if (!(plotPixels > 0)) return null;
    const l = { r1, r2, r3, r4 };
    const branches: Branch[] = only ? [only] : ['open', 'crossed'];
    const motion = omega2 !== null && alpha2 !== null ? { omega2, alpha2 } : null;
    try {
      return { linkage: l, plot: plotSeries(l, plotPixels, branches, { method, tol }, motion) };
    } catch {
      return null;
    }
  }, [r1, r2, r3, r4, plotPixels, only, method, tol, omega2, alpha2]);
}
