import { AnglePlotsPanel } from '../features/simulator/PlotsPanel';
import type { SimulatorSession } from './useSimulatorSession';

/** The session's angle (or rate) plots, as both layouts show them. */
export function SimulatorPlots({ session }: { session: SimulatorSession }) {
  const { state, dispatch, deg, rates, xMarks } = session;
  return (
    <AnglePlotsPanel
      deg={deg}
      showOther={state.display.showGhost}
      layout={state.display.plotLayout}
      dispatch={dispatch}
      xMarks={xMarks}
      kind={state.display.plotKind}
      rates={rates}
    />
  );
}
