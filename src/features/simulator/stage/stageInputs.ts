import type { AppState } from '../../../shared/state/appState';
import type { CycleResponse } from '../../../shared/solution';
import type { StageRequest } from './stageProtocol';

type SizeRequest = Extract<StageRequest, { type: 'size' }>;
type StateRequest = Extract<StageRequest, { type: 'state' }>;
type CycleRequest = Extract<StageRequest, { type: 'cycle' }>;

/**
 * What the live stage draws from besides the frame (the canvas's size, the committed state, the latest cycle), kept
 * by the page: each setter returns the messages a change needs (none for the same values again), and replay() all
 * there is, for a worker that starts after them.
 */
export interface StageInputs {
  /** The size message for a canvas of width × height CSS pixels at dpr, or null where it is the same. */
  size(width: number, height: number, dpr: number): SizeRequest | null;
  /** The state and cycle messages for what changed (compared by identity). */
  scene(state: AppState, cycle: CycleResponse | null, ghostShown: boolean): (StateRequest | CycleRequest)[];
  /** Every message kept so far, in the order a new worker needs them: size, state, cycle. */
  replay(): StageRequest[];
}

/** The live stage's inputs, kept for a worker that starts later. */
export function createStageInputs(): StageInputs {
  let size: SizeRequest | null = null;
  let state: StateRequest | null = null;
  let cycle: CycleRequest | null = null;
  return {
    size(width, height, dpr) {
      if (size && size.width === width && size.height === height && size.dpr === dpr) return null;
      size = { type: 'size', width, height, dpr };
      return size;
    },
    scene(nextState, nextCycle, ghostShown) {
      const out: (StateRequest | CycleRequest)[] = [];
      if (!state || state.state !== nextState || state.ghostShown !== ghostShown) {
        state = { type: 'state', state: nextState, ghostShown };
        out.push(state);
      }
      if (!cycle || cycle.cycle !== nextCycle) {
        cycle = { type: 'cycle', cycle: nextCycle };
        out.push(cycle);
      }
      return out;
    },
    replay: () => [size, state, cycle].filter((m) => m !== null),
  };
}
