import type { Direction } from './slices/motionSlice';
import { DESIGN_SLICE } from './slices/designSlice';
import { MOTION_SLICE } from './slices/motionSlice';
import { DISPLAY_SLICE } from './slices/displaySlice';
import { SOLVER_SLICE } from './slices/solverSlice';
import { SHELL_SLICE } from './slices/shellSlice';
import { LAB_SLICE } from './slices/labSlice';
import { SYN_PATH_SLICE } from './slices/synthesisSlice';
import { FORCES_SLICE } from './slices/forcesSlice';
import { SYN_MOTION_SLICE } from './slices/synMotionSlice';
import { SYN_FUNCTION_SLICE } from './slices/synFunctionSlice';
import { MECH_SLICE } from './slices/mechSlice';
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
 * Every slice of the app state, registered once (each slice file exports its Slice: summary, defaults, reducer, URL keys,
 * and as a type its own actions). AppState, DEFAULT_STATE, the Action union, the reducer, the URL table (shared/url/urlKeys.ts) and
 * the docs' lists of slices and keys are derived from it, in this order. A new slice is a slice file and one line
 * here (docs/ARCHITECTURE.md "To add a slice").
 */
export const SLICES = {
  design: DESIGN_SLICE,
  motion: MOTION_SLICE,
  display: DISPLAY_SLICE,
  solver: SOLVER_SLICE,
  shell: SHELL_SLICE,
  lab: LAB_SLICE,
  synPath: SYN_PATH_SLICE,
  forces: FORCES_SLICE,
  synMotion: SYN_MOTION_SLICE,
  synFunction: SYN_FUNCTION_SLICE,
  mech: MECH_SLICE,
};

/** The slices' names in SLICES's order (the URL table's order). */
export type SliceName = keyof typeof SLICES;

/** The slices' names, in SLICES's order. */
export const SLICE_NAMES = Object.keys(SLICES) as SliceName[];

/**
 * The whole shareable state of the app, one field per slice of SLICES; lengths in one user unit, angles in
 * degrees. Each slice (./slices) owns its fields, defaults, reducer and URL keys; this module only composes them.
 */
export type AppState = { [K in SliceName]: (typeof SLICES)[K]['defaults'] };

/** The report's linkage at 45 degrees on the open branch, with every slice at its default. */
export const DEFAULT_STATE = Object.fromEntries(SLICE_NAMES.map((name) => [name, SLICES[name].defaults])) as AppState;

/** Actions that more than one slice handles. */
export type SharedAction =
  /** One animation frame: theta2 and direction (motion) and the branch (design, flipped at a toggle). */
  | { type: 'animate'; theta2Deg: number; direction: Direction; branch: Branch }
  /** A preset: the design, theta2 (motion) and a fitted view (display). */
  | { type: 'applyPreset'; linkage: Linkage; theta2Deg: number; branch: Branch; coupler: CouplerPoint }
  | { type: 'replace'; state: AppState };

/** Every state change the UI can make: each slice's own actions and the shared ones. */
export type Action = { [K in SliceName]: NonNullable<(typeof SLICES)[K]['actionType']> }[SliceName] | SharedAction;

/** A slice's reducer, seen from the loop over SLICES. */
type AnyReducer = (s: unknown, action: Action) => unknown;

/** Changing page stops Play: no other page shows the animation. */
const STOP_PLAY: Action = { type: 'setPlaying', playing: false };

/**
 * The app's reducer: each slice's reducer sees every action (Redux's combineReducers); pure, and returns the
 * same object when no slice changed. Assumes values were validated at the edge.
 */
export function reducer(state: AppState, action: Action): AppState {
  if (action.type === 'replace') return action.state;
  const leavesPage = action.type === 'setPage' && action.page !== state.shell.page;
  const next = {} as Record<SliceName, unknown>;
  let changed = false;
  for (const name of SLICE_NAMES) {
    const sliceAction = leavesPage && name === 'motion' ? STOP_PLAY : action;
    next[name] = (SLICES[name].reducer as AnyReducer)(state[name], sliceAction);
    changed ||= next[name] !== state[name];
  }
  return changed ? (next as AppState) : state;
}
