import type { GifWorkerLike } from './gifClient';
import { GifChannelError, GifClient } from './gifClient';
import { gifFrameDelaysCs } from './gifTiming';
import type { GifWorkerResponse } from './gifProtocol';
import type { FrameSurface } from './frameSurface';
import { createFrameSurface, drawFrame } from './frameSurface';
import type { AnimationExportResult, ExportProgress, RenderFrame } from './types';
import type { AnimationFrame } from './animationFrames';

/** Frames spread over the cycle that the global palette is computed from. */
export const PALETTE_SAMPLE_FRAMES = 6;

/** Frames rendered ahead of the encoder: enough to keep it busy, few enough to bound memory (4 bytes a pixel each). */
export const FRAMES_IN_FLIGHT = 3;

/** Checked options of a GIF export (see AnimationExportOptions). */
export interface GifExportOptions {
  frames: readonly AnimationFrame[];
  width: number;
  height: number;
  viewWidth: number;
  viewHeight: number;
  fps: number;
  loop: boolean;
  background: string;
  renderFrame: RenderFrame;
  signal?: AbortSignal;
  onProgress?: (p: ExportProgress) => void;
}

/** Seams for tests and hosts: the drawing surface and the worker (null: encode on the main thread). */
export interface GifExportEnv {
  createSurface?: (width: number, height: number) => FrameSurface;
  createWorker?: () => GifWorkerLike | null;
}

function defaultWorker(): GifWorkerLike | null {
  if (typeof Worker === 'undefined') return null;
  return new Worker(new URL('../../../workers/gif.worker.ts', import.meta.url), {
    type: 'module',
  }) as unknown as GifWorkerLike;
}

/**
 * A started encoder: in a module worker when one loads, else on the main thread. Only a failing channel
 * (the worker script did not load or crashed) falls back; an error answer from the encoder is thrown.
 */
async function openEncoder(
  begin: { width: number; height: number; loop: boolean; samples: ArrayBuffer[] },
  env: GifExportEnv,
): Promise<GifClient> {
  let worker: GifWorkerLike | null = null;
  try {
    worker = (env.createWorker ?? defaultWorker)();
  } catch {
    worker = null;
  }
  if (worker) {
    const client = GifClient.overWorker(worker);
    try {
      // The samples are copied, not transferred: the fallback may need them again.
      await client.request({ type: 'begin', ...begin });
      return client;
    } catch (e) {
      client.close();
      if (!(e instanceof GifChannelError)) throw e;
    }
  }
  const client = await GifClient.onMainThread();
  await client.request({ type: 'begin', ...begin }, begin.samples);
  return client;
}

/**
 * Renders every frame and encodes them as an animated GIF (gifenc, loaded with the worker or on demand).
 * Frames are drawn here and sent to the encoder with at most FRAMES_IN_FLIGHT waiting; progress counts
 * encoded frames. Resolves to done with the file, or cancelled once the signal aborts.
 */
export async function exportGif(
  o: GifExportOptions,
  env: GifExportEnv = {},
): Promise<AnimationExportResult & { encoder?: GifClient['place'] }> {
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
  const client = await openEncoder({ width, height, loop: o.loop, samples }, env);
  const onAbort = () => client.close();
  signal?.addEventListener('abort', onAbort, { once: true });
  try {
    const delays = gifFrameDelaysCs(n, o.fps);
    const waiting: Promise<GifWorkerResponse>[] = [];
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
      const p = client.request({ type: 'frame', index: k, rgba, delayCs: delays[k] }, [rgba]);
      // Marked handled now: after a cancel, answers still waiting here reject and nobody awaits them.
      p.catch(() => undefined);
      waiting.push(p);
      if (waiting.length >= FRAMES_IN_FLIGHT) await settleOne();
    }
    while (waiting.length > 0) await settleOne();
    const last = await client.request({ type: 'finish' });
    if (last.type !== 'done') throw new Error(`the GIF encoder answered ${last.type} to finish`);
    return { status: 'done', blob: new Blob([last.bytes], { type: 'image/gif' }), encoder: client.place };
  } catch (e) {
    if (signal?.aborted) return cancelled;
    throw e;
  } finally {
    signal?.removeEventListener('abort', onAbort);
    client.close();
  }
}
