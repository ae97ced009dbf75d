import type { MechanismSpec } from '../../../mechanism';
import type { Playhead } from '../livePlayhead';
import type { MechScene } from '../mechScene';
import type { MechDriveRun, MechStageView } from './mechStageProtocol';

/**
 * The Mechanisms page's live stage: Play and a joint's drag drawn in a worker, on a canvas laid over the page's
 * (OffscreenCanvas), Play on the worker's own frame clock. The page's main thread then does not draw the linkage (nor
 * hand its pixels to the compositor) per frame; its playhead follows the stage's frames (the plots' markers, the
 * readouts). Where a worker cannot draw there is no stage (null) and the page draws as before
 * (workers/mechStageClient.ts makes one).
 */
export interface MechLiveStage {
  /** The stage's canvas, laid over the page's: handed to the worker once (a canvas goes once). */
  attach(canvas: HTMLCanvasElement): void;
  /** Where the page's canvas looks (its fit, pan and zoom, size). */
  setView(view: Omit<MechStageView, 'dpr'>): void;
  /** What the pictures are made of (mechScene.ts): sent when it changes, never per frame. */
  setScene(scene: MechScene): void;
  /** Plays from the playhead `from` as it stands at atMs (a requestAnimationFrame time of this page); a later call re-bases it. */
  play(from: Playhead, atMs: number, drive: MechDriveRun): void;
  /** Draws one picture (the input, or a joint's drag: the spec dragged) until the next show(), play() or stop(). */
  show(input: number, dragged: MechanismSpec | null): void;
  /** Stops drawing; the stage's canvas hides (showing() turns false). */
  stop(): void;
  /** Whether the stage draws (false once its worker failed or said it cannot animate: the page draws then). */
  usable(): boolean;
  /** The newest playhead the stage drew since the last play() or show(), or null before its first. */
  latest(): Playhead | null;
  /** Whether the stage's canvas shows: from its run's first frame drawn to stop(). */
  showing(): boolean;
  /** Adds a listener to changes of showing(); returns its removal. */
  subscribe(listener: () => void): () => void;
  /** Ends the worker (the page unmounts). */
  dispose(): void;
}

/** Makes the page's live stage, or null where there is none (the page's prop: the app passes the worker client's). */
export type MechStageFactory = () => MechLiveStage | null;
