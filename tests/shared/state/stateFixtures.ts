import type { AppState } from '../../../src/shared/state/appState';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';

type Slices = { [S in keyof AppState]: AppState[S] };
/** Every field of every slice, flat (field names are unique across slices). */
export type FlatState = Slices['design'] &
  Slices['motion'] &
  Slices['display'] &
  Slices['solver'] &
  Slices['shell'] & { labStepDeg: number };

/** Each flat field's slice, read from the default state. */
function sliceOf(field: string): keyof AppState {
  if (field === 'labStepDeg') return 'lab';
  for (const s of Object.keys(DEFAULT_STATE) as (keyof AppState)[]) if (field in DEFAULT_STATE[s]) return s;
  throw new Error(`no slice has a field ${field}`);
}

/** The state with fields given flat (tests read shorter so): withFields(DEFAULT_STATE, { theta2Deg: 90, showGhost: false }). */
export function withFields(base: AppState, patch: Partial<FlatState>): AppState {
  const next: Record<string, Record<string, unknown>> = {};
  for (const s of Object.keys(base) as (keyof AppState)[]) next[s] = { ...base[s] };
  for (const [field, value] of Object.entries(patch))
    next[sliceOf(field)][field === 'labStepDeg' ? 'stepDeg' : field] = value;
  return next as unknown as AppState;
}
