import type { ReactNode } from 'react';
import { Suspense, lazy, useMemo } from 'react';
import type { ForcePlotKind, Locale, PlotKind } from '../../shared/state/appState';
import type { SegmentedOption } from '../../shared/ui/Segmented';
import { forcesMessages } from './forcesMessages';

// The force plots (their chart modules and the cycle solver) load when one is first chosen.
const ForcePlots = lazy(() => import('./ForcePlots').then((m) => ({ default: m.ForcePlots })));

/** The force plots in the chooser's order. */
export const FORCE_PLOT_KINDS: readonly ForcePlotKind[] = ['torque', 'pinForces', 'bearing'];

/** Plots the forces add to the simulator's chooser: their choices and the view of a chosen one. */
export interface ForcePlotChoices {
  options: readonly SegmentedOption<PlotKind>[];
  render: (kind: PlotKind) => ReactNode;
}

function isForcePlot(kind: PlotKind): kind is ForcePlotKind {
  return (FORCE_PLOT_KINDS as readonly PlotKind[]).includes(kind);
}

/** "Torque", "Pin forces" and "Bearing load" for the plot chooser while Forces is on; null (none) while it is off. */
export function useForcePlotChoices(enabled: boolean, locale: Locale): ForcePlotChoices | null {
  return useMemo(() => {
    if (!enabled) return null;
    const t = forcesMessages.get(locale);
    const label: Record<ForcePlotKind, string> = {
      torque: t.plotTorque,
      pinForces: t.plotPinForces,
      bearing: t.plotBearing,
    };
    return {
      options: FORCE_PLOT_KINDS.map((k) => ({ value: k, label: label[k] })),
      render: (kind) =>
        isForcePlot(kind) ? (
          <Suspense fallback={<p className="note">…</p>}>
            <ForcePlots kind={kind} />
          </Suspense>
        ) : null,
    };
  }, [enabled, locale]);
}
