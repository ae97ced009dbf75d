import type { MechanismSpec } from '../../../mechanism';
import type { Bounds } from '../../../shared/canvas/view';
import type { ViewOffset } from '../../../shared/state/appState';
import type { Playhead } from '../livePlayhead';
import type { MechScene } from '../mechScene';

/** How Play moves the input: its rate (input units per second), the run it moves over, whether it turns fully. */
export interface MechDriveRun {
  ratePerS: number;
  range: [number, number];
  fullTurn: boolean;
}

/** Where the canvas looks: the world box it fits, the user's pan and zoom, its size (CSS pixels) and pixel ratio. */
export interface MechStageView {
  bounds: Bounds;
  offset: ViewOffset;
  width: number;
  height: number;
  dpr: number;
}

/**
 * The page to the Mechanisms page's live stage worker (workers/mechStage.worker.ts, its loop mechStageLoop.ts). Times
 * are epoch ms (timeOrigin + now), so the two clocks agree. play: Play from the playhead `from` as it stood at
 * atEpochMs; show: one picture (input, or a joint's drag: the spec dragged, drawn as drawn) until the next request.
 */
export type MechStageRequest =
  | { type: 'canvas'; canvas: OffscreenCanvas }
  | { type: 'view'; view: MechStageView }
  | { type: 'scene'; scene: MechScene }
  | { type: 'play'; id: number; from: Playhead; atEpochMs: number; drive: MechDriveRun }
  | { type: 'show'; id: number; input: number; dragged: MechanismSpec | null }
  | { type: 'stop' };

/** What a drawn frame shows: the playhead (Play) or input drawn, the pose's digest and the chosen joint's place. */
export interface MechFrameDrawn {
  playhead: Playhead;
  /** The pose's poseDigest and the chosen joint's selectedAt, for tests and tools. */
  pose: string;
  selectedAt: string;
}

/**
 * The worker to the page: a frame of run `id` drawn at atEpochMs and on screen by shownEpochMs (Play draws in its
 * animation frames, so the two are one there; a show is told at the next), its drawing's time (ms, the worker's
 * clock); or that this browser's workers cannot animate; or that it is ready (it has drawn once, unseen).
 */
export type MechStageReply =
  | ({ type: 'drawn'; id: number; atEpochMs: number; shownEpochMs: number; drawMs: number } & MechFrameDrawn)
  | { type: 'unsupported' }
  | { type: 'ready' };
