import { LAB_TOLERANCES } from '../../../study/options';
import { SWEEP_METHODS } from '../../../solver/methods';
import type { SweepMethod } from '../../../solver/types';
import { choiceCodec, enumCodec, integerCodec, nullableCodec } from '../../url/urlCodec';
import type { UrlKey } from '../../url/urlKey';
import { sameText, sliceLens, urlKey } from '../../url/urlKey';
import type { Action } from '../appState';
import type { Slice } from '../slice';
import { clamp } from './motionSlice';

/** Which start the NR convergence plot and panel show: the previous cycle point or a fixed cold guess. */
export type NrStart = 'continuation' | 'cold';

/** The solver slice: how the cycle is swept and which NR start the convergence view shows. */
export interface SolverState {
  /** Method of the cycle sweep and of the NR runs shown at the current theta2 (chosen in the solver lab). */
  method: SweepMethod;
  /** NR tolerance for the chosen method; null = the method's default (full precision; 1e-9 absolute for seed). */
  tol: number | null;
  nrStart: NrStart;
  /** Intervals per cycle: the sweep has samples + 1 points from 0 to 360 degrees. */
  samples: number;
}

/** Actions only the solver slice handles. */
export type SolverAction =
  | { type: 'setMethod'; method: SweepMethod; tol: number | null }
  | { type: 'setNrStart'; start: NrStart }
  | { type: 'setSamples'; samples: number };

/** Smallest and largest sample counts per cycle accepted from the UI or the URL. */
export const SAMPLES_MIN = 12;
export const SAMPLES_MAX = 36000;

/** Sample counts offered in the settings (intervals per cycle). */
export const SAMPLE_CHOICES: readonly number[] = [360, 720, 1800, 3600];

/** Newton at full precision, continuation starts, 360 intervals per cycle. */
export const DEFAULT_SOLVER: SolverState = { method: 'newton', tol: null, nrStart: 'continuation', samples: 360 };

/** The solver slice's reducer: pure, returns the same object when nothing changes. */
export function solverReducer(s: SolverState, action: Action): SolverState {
  switch (action.type) {
    case 'setMethod':
      if (action.method === s.method && action.tol === s.tol) return s;
      return { ...s, method: action.method, tol: action.tol };
    case 'setNrStart':
      return { ...s, nrStart: action.start };
    case 'setSamples':
      return { ...s, samples: Math.round(clamp(action.samples, SAMPLES_MIN, SAMPLES_MAX)) };
    default:
      return s;
  }
}

const field = sliceLens('solver');

/** The solver's URL keys: nr, n, m, tol. */
export const SOLVER_URL_KEYS: readonly UrlKey<unknown>[] = [
  urlKey(
    'nr',
    enumCodec([
      ['cont', 'continuation'],
      ['cold', 'cold'],
    ] as const),
    field('nrStart'),
  ),
  urlKey('n', integerCodec(SAMPLES_MIN, SAMPLES_MAX), field('samples')),
  urlKey('m', enumCodec(sameText(SWEEP_METHODS)), field('method')),
  urlKey('tol', nullableCodec(choiceCodec(LAB_TOLERANCES), 'default'), field('tol')),
];

/** The solver slice's registration in SLICES (appState.ts). */
export const SOLVER_SLICE: Slice<SolverState, SolverAction> = {
  summary: 'how the cycle is swept: method, tolerance, NR start, samples',
  defaults: DEFAULT_SOLVER,
  reducer: solverReducer,
  urlKeys: SOLVER_URL_KEYS,
};
