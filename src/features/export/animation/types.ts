import type { AnimationFrame } from './animationFrames';
import type { FrameContext } from '../../../shared/linkage/linkageFrame';

/** A 2D context a frame is drawn on (the linkage drawer's): a detached canvas's or an OffscreenCanvas's. */
export type { FrameContext };

/**
 * Draws one frame. ctx is already scaled and letterboxed so that the drawing uses viewWidth x viewHeight
 * CSS pixels, exactly as on screen (pass the same view transform as the canvas uses); the area outside is clipped.
 */
export type RenderFrame = (
  ctx: FrameContext,
  frame: AnimationFrame,
  viewWidth: number,
  viewHeight: number,
) => void | Promise<void>;

/** Animation file formats. */
export type AnimationFormat = 'gif' | 'webm';

/** How far an export is: frames encoded (GIF) or recorded (WebM) out of frameCount, and that as a fraction 0..1. */
export interface ExportProgress {
  framesDone: number;
  frameCount: number;
  fraction: number;
}

/** Options of exportAnimation. */
export interface AnimationExportOptions {
  format: AnimationFormat;
  /** The frames of one cycle (planAnimationFrames); at least one. */
  frames: readonly AnimationFrame[];
  /** Output size in device pixels (exportSizePx). */
  width: number;
  height: number;
  /** Size of the view renderFrame draws, CSS pixels; defaults to width x height. Letterboxed into the output. */
  viewWidth?: number;
  viewHeight?: number;
  /** Frames per second, > 0 (GIF delays are whole centiseconds, at most 50 FPS; WebM records in real time). */
  fps: number;
  /** GIF: loop forever (true) or play once. WebM ignores it (players loop on their own). */
  loop: boolean;
  renderFrame: RenderFrame;
  /** CSS colour of the letterbox bars; default white. */
  background?: string;
  /** Aborting cancels the export; the promise then resolves to { status: 'cancelled' }. */
  signal?: AbortSignal;
  onProgress?: (p: ExportProgress) => void;
}

/** The checked options every encoder gets: exportAnimation's, with the view size and background filled in. */
export interface EncoderOptions {
  frames: readonly AnimationFrame[];
  width: number;
  height: number;
  viewWidth: number;
  viewHeight: number;
  fps: number;
  background: string;
  renderFrame: RenderFrame;
  signal?: AbortSignal;
  onProgress?: (p: ExportProgress) => void;
}

/** Outcome of exportAnimation: a file, a cancel, or a browser that cannot make this format (with a reason to show). */
export type AnimationExportResult =
  { status: 'done'; blob: Blob } | { status: 'cancelled' } | { status: 'unsupported'; reason: string };
