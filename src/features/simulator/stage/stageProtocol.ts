import type { InputRangeDeg } from '../../../shared/state/animation';
import type { AppState } from '../../../shared/state/appState';
import type { PlayFrame } from '../../../shared/state/playhead';
import type { CycleResponse } from '../../../shared/solution';

/**
 * The page to the live stage's worker (workers/stage.worker.ts, its loop stageLoop.ts). Times are epoch ms
 * (timeOrigin + now): the two clocks agree.
 */
export type StageRequest =
  | { type: 'canvas'; canvas: OffscreenCanvas }
  | { type: 'size'; width: number; height: number; dpr: number }
  | { type: 'state'; state: AppState; ghostShown: boolean }
  | { type: 'cycle'; cycle: CycleResponse | null }
  | { type: 'play'; id: number; frame: PlayFrame; atEpochMs: number; speedDegPerFrame: number; range: InputRangeDeg }
  | { type: 'show'; id: number; frame: PlayFrame }
  | { type: 'stop' };

/**
 * The worker to the page: a frame of play or show `id` drawn at atEpochMs and on screen by shownEpochMs (the next
 * animation frame of the worker after a show; Play draws in its animation frames, so the two are one there), or that
 * this browser's workers cannot animate, or that it is ready (it has the canvas and the state, its code has run
 * once: see stageLoop's warmUp). drawMs: the worker's time for the frame's scene and drawing.
 */
export type StageReply =
  | { type: 'drawn'; id: number; frame: PlayFrame; atEpochMs: number; shownEpochMs: number; drawMs: number }
  | { type: 'unsupported' }
  | { type: 'ready' };
