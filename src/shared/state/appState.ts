import type { DesignAction, DesignState } from './slices/designSlice';
import { DEFAULT_DESIGN, designReducer } from './slices/designSlice';
import type { DisplayAction, DisplayState } from './slices/displaySlice';
import { DEFAULT_DISPLAY, displayReducer } from './slices/displaySlice';
import type { LabAction, LabState } from './slices/labSlice';
import { DEFAULT_LAB, labReducer } from './slices/labSlice';
import type { Direction, MotionAction, MotionState } from './slices/motionSlice';
import { DEFAULT_MOTION, motionReducer } from './slices/motionSlice';
import type { ShellAction, ShellState } from './slices/shellSlice';
import { DEFAULT_SHELL, shellReducer } from './slices/shellSlice';
import type { SolverAction, SolverState } from './slices/solverSlice';
import { DEFAULT_SOLVER, solverReducer } from './slices/solverSlice';
import type { SynPathAction, SynPathState } from './slices/synthesisSlice';
import { DEFAULT_SYN_PATH, synPathReducer } from './slices/synthesisSlice';
import type { SynMotionAction, SynMotionState } from './slices/synMotionSlice';
import { DEFAULT_SYN_MOTION, synMotionReducer } from './slices/synMotionSlice';
import type { SynFunctionAction, SynFunctionState } from './slices/synFunctionSlice';
import { DEFAULT_SYN_FUNCTION, synFunctionReducer } from './slices/synFunctionSlice';
import type { ForcesAction, ForcesState } from './slices/forcesSlice';
import { DEFAULT_FORCES, forcesReducer } from './slices/forcesSlice';
import type { Branch, Linkage } from '../../solver/types';
import type { CouplerPoint } from './slices/designSlice';

export type { CouplerPoint, DesignState } from './slices/designSlice';
export type {
  DisplayState,
  ForcePlotKind,
  MotionPlotKind,
  PlotKind,
  PlotLayout,
  ViewFlag,
  ViewOffset,
} from './slices/displaySlice';
export { DEFAULT_DISPLAY, FITTED_VIEW } from './slices/displaySlice';
export type { LabState } from './slices/labSlice';
export type { Direction, MotionState } from './slices/motionSlice';
export { NOMINAL_FPS, SPEED_MAX, SPEED_MIN, SPEED_STEP, clamp, normalizeTheta2Deg } from './slices/motionSlice';
export type { Locale, Page, ShellState } from './slices/shellSlice';
export type { NrStart, SolverState } from './slices/solverSlice';
export { SAMPLES_MAX, SAMPLES_MIN, SAMPLE_CHOICES } from './slices/solverSlice';
export type { PathInput, PathTiming, PivotBox, SynPathState, SynthesisMode } from './slices/synthesisSlice';

/**
 * The whole shareable state of the app, one slice per concern; lengths in one user unit, angles in degrees.
 * Each slice (./slices) owns its fields, defaults, reducer and URL keys; this module only composes them.
 */
export interface AppState {
  /** What the linkage is: lengths, branch, coupler point. */
  design: DesignState;
  /** Where the crank is, how it plays, and the input motion of the rate analysis. */
  motion: MotionState;
  /** What the canvas and the plots show. */
  display: DisplayState;
  /** How the cycle is swept. */
  solver: SolverState;
  /** The language and the page. */
  shell: ShellState;
  /** The solver lab's own settings. */
  lab: LabState;
  /** The synthesis page's mode and its Path mode's task. */
  synPath: SynPathState;
  /** The length unit, and the forces: on or off, mass model, loads, force arrows. */
  forces: ForcesState;
  /** The synthesis page's Motion mode: poses and the pivots or dyads chosen. */
  synMotion: SynMotionState;
  /** The synthesis page's Function mode: y = f(x), its ranges and precision points. */
  synFunction: SynFunctionState;
}

/** The report's linkage at 45 degrees on the open branch, with every slice at its default. */
export const DEFAULT_STATE: AppState = {
  design: DEFAULT_DESIGN,
  motion: DEFAULT_MOTION,
  display: DEFAULT_DISPLAY,
  solver: DEFAULT_SOLVER,
  shell: DEFAULT_SHELL,
  lab: DEFAULT_LAB,
  synPath: DEFAULT_SYN_PATH,
  forces: DEFAULT_FORCES,
  synMotion: DEFAULT_SYN_MOTION,
  synFunction: DEFAULT_SYN_FUNCTION,
};

/** Actions that more than one slice handles. */
export type SharedAction =
  /** One animation frame: theta2 and direction (motion) and the branch (design, flipped at a toggle). */
  | { type: 'animate'; theta2Deg: number; direction: Direction; branch: Branch }
  /** A preset: the design, theta2 (motion) and a fitted view (display). */
  | { type: 'applyPreset'; linkage: Linkage; theta2Deg: number; branch: Branch; coupler: CouplerPoint }
  | { type: 'replace'; state: AppState };

/** Every state change the UI can make. */
export type Action =
  | DesignAction
  | MotionAction
  | DisplayAction
  | SolverAction
  | ShellAction
  | LabAction
  | SynPathAction
  | ForcesAction
  | SynMotionAction
  | SynFunctionAction
  | SharedAction;

/**
 * The app's reducer: each slice's reducer sees every action (Redux's combineReducers); pure, and returns the
 * same object when no slice changed. Assumes values were validated at the edge.
 */
export function reducer(state: AppState, action: Action): AppState {
  if (action.type === 'replace') return action.state;
  // Changing page stops Play: no other page shows the animation.
  const leavesPage = action.type === 'setPage' && action.page !== state.shell.page;
  const motion = leavesPage
    ? motionReducer(state.motion, { type: 'setPlaying', playing: false })
    : motionReducer(state.motion, action);
  const next: AppState = {
    design: designReducer(state.design, action),
    motion,
    display: displayReducer(state.display, action),
    solver: solverReducer(state.solver, action),
    shell: shellReducer(state.shell, action),
    lab: labReducer(state.lab, action),
    synPath: synPathReducer(state.synPath, action),
    forces: forcesReducer(state.forces, action),
    synMotion: synMotionReducer(state.synMotion, action),
    synFunction: synFunctionReducer(state.synFunction, action),
  };
  const changed = (Object.keys(next) as (keyof AppState)[]).some((k) => next[k] !== state[k]);
  return changed ? next : state;
}
