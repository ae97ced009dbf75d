import { useCallback, useMemo, useState } from 'react';
import type { AppState } from '../shared/state/appState';
import { Playhead } from '../shared/state/playhead';
import { getMessages } from '../shared/i18n/i18n';
import { deadCentreXMarks } from '../shared/charts/transmissionInputs';
import { useShownFrame } from '../shared/linkage/useShownFrame';
import { useJobClient } from '../shared/jobs/useJobClient';
import { useCycleTable } from '../features/simulator/useCycleTable';
import { createSolverClient } from '../workers/solverClient';
import { createLiveStage } from '../workers/stageClient';
import { computeCycle, computePoint } from '../features/simulator/solve/compute';
import type { FirstAnswers } from '../features/simulator/useSolver';
import { useAnimation } from '../features/simulator/useAnimation';
import { useCanvasEdits } from '../features/simulator/useCanvasEdits';
import { useCycleFacts } from '../features/simulator/useCycleFacts';
import { useDesignMetrics } from '../features/simulator/useDesignMetrics';
import { useDrawnMark } from '../features/simulator/useDrawnMark';
import { usePlotPixels } from '../features/simulator/usePlotPixels';
import { useSimulator } from '../features/simulator/useSimulator';
import { forceColumnsFor } from '../features/forces/tableForces';
import type { ShownViews } from '../features/simulator/useSimulator';
import { useExports } from '../features/export/useExports';
import { useAppHistory } from './useAppHistory';

/** The first cycle and pose are solved on the main thread, with the worker's own solves (useSolver's FirstAnswers). */
const FIRST_ANSWERS: FirstAnswers = { cycle: computeCycle, point: computePoint };

/** Everything useSimulatorSession gives a layout. */
export type SimulatorSession = ReturnType<typeof useSimulatorSession>;

/** Which views a layout shows for a state, given the plots card's device-pixel width (0 while it is hidden). */
export type ShownFor = (state: AppState, plotPixels: number) => ShownViews;

/**
 * Everything a layout of the simulator needs, composed once for the full app and the widget: the state and its
 * solver answers, the cycle's facts and table, the design metrics, Play's playhead and step, the canvas edits and
 * the export handlers. `shownFor` says which views show (only those are solved); `tableShown` whether the numbers
 * panel (and so the n-point table) is on screen. Marks 'fourbar:cycle-drawn' and 'fourbar:plot-drawn' for bench:ui.
 * The state keeps its history (useAppHistory): undo, redo, canUndo and canRedo come with it.
 */
export function useSimulatorSession(initial: AppState, shownFor: ShownFor, tableShown: boolean) {
  const { plotsRef, plotPixels } = usePlotPixels();
  const views = useCallback((s: AppState) => shownFor(s, plotPixels), [shownFor, plotPixels]);
  // The one solver client (every feature's solver jobs) is made here, where the features' job tables meet.
  const { client, mode: solverMode, reason: solverReason } = useJobClient(createSolverClient, 'Solver');
  // The state with undo and redo (shared/state/history.ts): the URL and every view follow its present.
  const history = useAppHistory(initial);
  const sim = useSimulator(history.state, history.dispatch, views, client, FIRST_ANSWERS);
  const { state, dispatch, cycle, point, plot } = sim;
  const solverChoice = useMemo(
    () => ({ method: state.solver.method, tol: state.solver.tol }),
    [state.solver.method, state.solver.tol],
  );
  const table = useCycleTable(
    client,
    state.design.linkage,
    state.solver.samples,
    state.design.branch,
    solverChoice,
    tableShown,
  );
  const t = getMessages(state.shell.locale);
  const facts = useCycleFacts(cycle, plot, state.motion.direction);
  const design = useDesignMetrics(state.design.linkage, state.design.branch);
  const xMarks = useMemo(() => deadCentreXMarks(design?.metrics ?? null, t), [design, t]);
  const { shown, onShown } = useShownFrame();
  const exports = useExports({ state, point, shown, cycle, client, deg: facts.deg, t, forces: forceColumnsFor(state) });
  const [playhead] = useState(() => new Playhead());
  // Play's linkage drawn in a worker where the browser allows it (null: the page draws it).
  const [stage] = useState(createLiveStage);
  const { step: onStep, scrub } = useAnimation(state, dispatch, facts.rangeDeg, playhead, stage);
  const onViewChange = useCallback(
    (view: AppState['display']['view']) => dispatch({ type: 'setView', view }),
    [dispatch],
  );
  const edits = useCanvasEdits(dispatch);
  useDrawnMark('fourbar:cycle-drawn', cycle);
  useDrawnMark('fourbar:plot-drawn', plot);
  return {
    ...sim,
    client,
    solverMode,
    solverReason,
    ...facts,
    ...edits,
    ...exports,
    t,
    table,
    design,
    xMarks,
    onShown,
    /** The frame the linkage view drew last (the printed report draws it). */
    shown,
    playhead,
    /** The live stage that draws Play's frames in a worker (null where the page draws them). */
    stage,
    onStep,
    /** The θ2 drag (slider, crank pin): moves the playhead, the state follows (FramePoseProvider provides it). */
    scrub,
    onViewChange,
    plotsRef,
    undo: history.undo,
    redo: history.redo,
    canUndo: history.canUndo,
    canRedo: history.canRedo,
  };
}
