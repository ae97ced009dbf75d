import { LAB_STEPS_DEG } from '../../../study/options';
import { choiceCodec } from '../../url/urlCodec';
import type { UrlKey } from '../../url/urlKey';
import { optionalKey, sliceLens } from '../../url/urlKey';
import type { Action } from '../appState';
import type { Slice } from '../slice';

/** The solver lab's slice: the input step of its cycle. */
export interface LabState {
  /** Input step of the solver lab's cycle, degrees (one of LAB_STEPS_DEG). */
  stepDeg: number;
}

/** Actions only the lab slice handles. */
export type LabAction = { type: 'setLabStep'; stepDeg: number };

/** A 1 degree step. */
export const DEFAULT_LAB: LabState = { stepDeg: 1 };

/** The lab slice's reducer: pure, returns the same object when nothing changes. */
export function labReducer(s: LabState, action: Action): LabState {
  if (action.type !== 'setLabStep' || action.stepDeg === s.stepDeg) return s;
  return { ...s, stepDeg: action.stepDeg };
}

/** The lab's URL key: lstep when it is not 1 degree. */
export const LAB_URL_KEYS: readonly UrlKey<unknown>[] = [
  optionalKey('lstep', choiceCodec(LAB_STEPS_DEG), sliceLens('lab')('stepDeg'), DEFAULT_LAB.stepDeg),
];

/** The lab slice's registration in SLICES (appState.ts). */
export const LAB_SLICE: Slice<LabState, LabAction> = {
  summary: "the solver lab's step",
  defaults: DEFAULT_LAB,
  reducer: labReducer,
  urlKeys: LAB_URL_KEYS,
};
