import type { WorkerLike } from '../../../shared/jobs/jobClient';
import { JobClient } from '../../../shared/jobs/jobClient';
import { createMainThreadWorker } from '../../../shared/jobs/mainThread';
import { gifFrameDelaysCs } from './gifTiming';
import type { GifJobs } from './gifJobs';
import { gifJobs } from './gifJobs';
import type { FrameSurface } from './frameSurface';
import { createFrameSurface, drawFrame } from './frameSurface';
import type { AnimationExportResult, EncoderOptions } from './types';
import type { AnimationFrame } from './animationFrames';

/** Frames spread over the cycle that the global palette is computed from. */
export const PALETTE_SAMPLE_FRAMES = 6;

/** Frames rendered ahead of the encoder: enough to keep it busy, few enough to bound memory (4 bytes a pixel each). */
export const FRAMES_IN_FLIGHT = 3;

/** Checked options of a GIF export: an encoder's, and whether the GIF loops forever. */
export interface GifExportOptions extends EncoderOptions {
  loop: boolean;
}

/** Seams for tests and hosts: the drawing surface and the worker (null: encode on the main thread). */
export interface GifExportEnv {
  createSurface?: (width: number, height: number) => FrameSurface;
  createWorker?: () => WorkerLike | null;
}

/** Where a GIF was encoded. */
export type GifEncoderPlace = 'worker' | 'main-thread';

function defaultWorker(): WorkerLike | null {
  if (typeof Worker === 'undefined') return null;
  return new Worker(new URL('../../../workers/gif.worker.ts', import.meta.url), {
    type: 'module',
  }) as unknown as WorkerLike;
}

/**
 * The encoder's client: a module worker when one loads, else the main thread, loading the encoder (gifenc)
 * there on demand. Never restarted: the worker holds the encode, so only a channel that fails (the worker did
 * not load, or crashed) moves on to the main thread, resending what was in flight; an encoder error is thrown.
 */
function openEncoder(env: GifExportEnv): JobClient<GifJobs> {
  return new JobClient(gifJobs, {
    createWorker: () => {
      const worker = (env.createWorker ?? defaultWorker)();
      if (!worker) throw new Error('no module worker here');
      return worker;
    },
    createFallback: () => createMainThreadWorker(() => import('./gifSession').then((m) => m.createGifSession())),
    restarts: 0,
  });
}

/**
 * Renders every frame and encodes them as an animated GIF (gifenc, loaded with the worker or on demand).
 * Frames are drawn here and sent to the encoder with at most FRAMES_IN_FLIGHT waiting; progress counts
 * encoded frames. Resolves to done with the file, or cancelled once the signal aborts.
 */
export async function exportGif(
  o: GifExportOptions,
  env: GifExportEnv = {},
): Promise<AnimationExportResult & { encoder?: GifEncoderPlace }> {
  const { frames, width, height, signal } = o;
  const n = frames.length;
  const cancelled = { status: 'cancelled' } as const;
  if (signal?.aborted) return cancelled;
  const surface = (env.createSurface ?? createFrameSurface)(width, height);
  const draw = (f: AnimationFrame) => drawFrame(surface, f, o);
  const samples: ArrayBuffer[] = [];
  const sampleCount = Math.min(n, PALETTE_SAMPLE_FRAMES);
  for (let i = 0; i < sampleCount; i++) {
    await draw(frames[Math.floor((i * n) / sampleCount)]);
    samples.push(surface.readPixels().buffer as ArrayBuffer);
    if (signal?.aborted) return cancelled;
  }
  const client = openEncoder(env);
  // Disposing resolves every pending call to null: the loop below then sees the abort and stops.
  const onAbort = () => client.dispose();
  signal?.addEventListener('abort', onAbort, { once: true });
  try {
    await client.run('begin', { width, height, loop: o.loop, samples }).result;
    const delays = gifFrameDelaysCs(n, o.fps);
    const waiting: Promise<unknown>[] = [];
    let done = 0;
    const report = () => o.onProgress?.({ framesDone: done, frameCount: n, fraction: done / n });
    const settleOne = async () => {
      await waiting.shift();
      done++;
      report();
    };
    report();
    for (let k = 0; k < n; k++) {
      if (signal?.aborted) return cancelled;
      await draw(frames[k]);
      const rgba = surface.readPixels().buffer as ArrayBuffer;
      const p = client.run('frame', { index: k, rgba, delayCs: delays[k] }).result;
      // Marked handled now: after a failure, answers still waiting here reject and nobody awaits them.
      p.catch(() => undefined);
      waiting.push(p);
      if (waiting.length >= FRAMES_IN_FLIGHT) await settleOne();
    }
    while (waiting.length > 0) await settleOne();
    const last = await client.run('finish', {}).result;
    if (!last || signal?.aborted) return cancelled;
    const encoder: GifEncoderPlace = client.mode === 'main-thread' ? 'main-thread' : 'worker';
    return { status: 'done', blob: new Blob([last.bytes], { type: 'image/gif' }), encoder };
  } catch (e) {
    if (signal?.aborted) return cancelled;
    throw e;
  } finally {
    signal?.removeEventListener('abort', onAbort);
    client.dispose();
  }
}
