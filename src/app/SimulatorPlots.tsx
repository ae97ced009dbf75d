import { AnglePlotsPanel } from '../features/simulator/PlotsPanel';
import { useForcePlotChoices } from '../features/forces/useForcePlotChoices';
import type { SimulatorSession } from './useSimulatorSession';

/**
 * The session's angle, rate or (while Forces is on) force plots, as both layouts show them; `secondHeld` holds the
 * second angle chart (AnglePlotsPanelProps.secondHeld).
 */
export function SimulatorPlots({ session, secondHeld = false }: { session: SimulatorSession; secondHeld?: boolean }) {
  const { state, dispatch, deg, rates, xMarks } = session;
  // The forces add their plots to the chooser while they are on.
  const forcePlots = useForcePlotChoices(state.forces.enabled, state.shell.locale);
  return (
    <AnglePlotsPanel
      deg={deg}
      showOther={state.display.showGhost}
      layout={state.display.plotLayout}
      dispatch={dispatch}
      xMarks={xMarks}
      kind={state.display.plotKind}
      rates={rates}
      extra={forcePlots}
      secondHeld={secondHeld}
    />
  );
}
