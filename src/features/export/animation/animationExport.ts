import { MAX_SIDE_PX } from './exportSize';
import type { GifExportEnv } from './gifExport';
import { exportGif } from './gifExport';
import type { AnimationExportOptions, AnimationExportResult } from './types';
import { recordWebm } from './webmRecorder';

/** Highest frame rate accepted, frames per second (GIF plays at most 50; WebM records up to this). */
export const MAX_FPS = 60;

function checkSide(name: string, v: number, max: number): void {
  if (!Number.isInteger(v) || v < 1 || v > max)
    throw new Error(`${name} must be an integer from 1 to ${max}, got ${v}`);
}

function checkPositive(name: string, v: number): void {
  if (!(v > 0) || !Number.isFinite(v)) throw new Error(`${name} must be a positive finite number, got ${v}`);
}

/**
 * Exports one cycle as an animated GIF (gifenc, in a module worker where it loads, else on the main thread)
 * or a WebM video (MediaRecorder, in real time). Each frame is drawn by options.renderFrame on a canvas of
 * width x height pixels, the view letterboxed into it. Resolves to { status: 'done', blob },
 * { status: 'cancelled' } after options.signal aborts, or { status: 'unsupported', reason } where the
 * browser cannot make the format. Throws for options that are not an export at all (no frames, a size
 * outside 1..4096 pixels, a frame rate outside (0, 60]), naming the option and value.
 * Load this module with a dynamic import: it is not needed before someone exports.
 */
export async function exportAnimation(
  options: AnimationExportOptions,
  env: GifExportEnv = {},
): Promise<AnimationExportResult> {
  const { frames, width, height, fps } = options;
  if (frames.length === 0) throw new Error('frames must hold at least one frame, got 0');
  checkSide('width', width, MAX_SIDE_PX);
  checkSide('height', height, MAX_SIDE_PX);
  checkPositive('fps', fps);
  if (fps > MAX_FPS) throw new Error(`fps must be at most ${MAX_FPS}, got ${fps}`);
  const viewWidth = options.viewWidth ?? width;
  const viewHeight = options.viewHeight ?? height;
  checkPositive('viewWidth', viewWidth);
  checkPositive('viewHeight', viewHeight);
  const checked = { ...options, viewWidth, viewHeight, background: options.background ?? '#ffffff' };
  switch (options.format) {
    case 'gif':
      return exportGif(checked, env);
    case 'webm':
      return recordWebm(checked);
    default:
      throw new Error(`format must be 'gif' or 'webm', got ${JSON.stringify(options.format)}`);
  }
}
