import { GifReader } from 'omggif';
import { describe, expect, it } from 'vitest';
import { exportAnimation } from '../../../../src/features/export/animation/animationExport';
import type { AnimationFrame } from '../../../../src/features/export/animation/animationFrames';
import { planAnimationFrames } from '../../../../src/features/export/animation/animationFrames';
import type { WorkerLike } from '../../../../src/shared/jobs/jobClient';
import { serveJobs } from '../../../../src/shared/jobs/jobExpose';
import { FRAMES_IN_FLIGHT, PALETTE_SAMPLE_FRAMES } from '../../../../src/features/export/animation/gifExport';
import { gifFrameDelaysCs } from '../../../../src/features/export/animation/gifTiming';
import { createGifSession } from '../../../../src/features/export/animation/gifSession';
import type {
  AnimationExportOptions,
  ExportProgress,
  RenderFrame,
} from '../../../../src/features/export/animation/types';
import { createFakeSurface } from './fakeSurface';

const VIEW = { width: 100, height: 100 };
/** 16:9 output for a square view: the view is scaled by 0.9 to 90 x 90 and centred, 35 px bars left and right. */
const OUT = { width: 160, height: 90 };
const BAR_PX = 35;
const FULL = { full: true, intervals: [{ lo: -180, hi: 180 }] };

/** 36 frames of a full turn from 0°. */
const FRAMES = planAnimationFrames({
  theta2Deg: 0,
  direction: 1,
  branch: 'open',
  range: FULL,
  framesPerCycle: 36,
}).frames;

/** Where the test drawing puts its marker for a frame: x in view pixels, 0..80 over the turn. */
function markerX(f: AnimationFrame): number {
  return Math.round((f.theta2Rad / (2 * Math.PI)) * 80);
}

/** Grey view, a 10 x 10 blue marker whose x follows θ2, and a red band past the view's left edge (clipped). */
const drawMarker: RenderFrame = (ctx, f, w, h) => {
  ctx.fillStyle = '#c02020';
  ctx.fillRect(-50, 0, 50, h);
  ctx.fillStyle = '#dddddd';
  ctx.fillRect(0, 0, w, h);
  ctx.fillStyle = '#1030c0';
  ctx.fillRect(markerX(f), 40, 10, 10);
};

function baseOptions(over: Partial<AnimationExportOptions> = {}): AnimationExportOptions {
  return {
    format: 'gif',
    frames: FRAMES,
    width: OUT.width,
    height: OUT.height,
    viewWidth: VIEW.width,
    viewHeight: VIEW.height,
    fps: 24,
    loop: true,
    renderFrame: drawMarker,
    background: '#ffffff',
    ...over,
  };
}

const noWorker = { createSurface: createFakeSurface, createWorker: () => null };

/** Decoded and composited frames (omggif; disposal 1 keeps the last frame). */
async function decode(blob: Blob) {
  const bytes = new Uint8Array(await blob.arrayBuffer());
  const reader = new GifReader(bytes);
  const canvas = new Uint8ClampedArray(reader.width * reader.height * 4);
  const frames: Uint8ClampedArray[] = [];
  for (let i = 0; i < reader.numFrames(); i++) {
    reader.decodeAndBlitFrameRGBA(i, canvas);
    frames.push(canvas.slice());
  }
  return { reader, frames, delays: frames.map((_, i) => reader.frameInfo(i).delay) };
}

function pixel(rgba: Uint8ClampedArray, x: number, y: number): number[] {
  const i = (y * OUT.width + x) * 4;
  return [rgba[i], rgba[i + 1], rgba[i + 2]];
}

/**
 * A fake worker that serves the real session's jobs, answering asynchronously as a worker would (both directions
 * cross a structured clone with their transfer lists). failOnLoad: an error event instead of any answer, as a
 * script that did not load gives; failWith: the encoder throws that at begin.
 */
function fakeWorker(opts: { failOnLoad?: boolean; failWith?: string } = {}) {
  const listeners: Record<string, ((e: Event) => void)[]> = {};
  const session = createGifSession();
  const failWith = opts.failWith;
  const handlers = failWith
    ? {
        ...session,
        begin: () => {
          throw new Error(failWith);
        },
      }
    : session;
  let toHandlers: ((e: MessageEvent) => void) | null = null;
  serveJobs(handlers, {
    postMessage: (message, transfer) => {
      const data = structuredClone(message, { transfer });
      for (const l of listeners.message ?? []) l({ data } as MessageEvent);
    },
    addEventListener: (_type, l) => {
      toHandlers = l;
    },
  });
  const log: string[] = [];
  const w: WorkerLike & { log: string[] } = {
    log,
    postMessage(req, transfer = []) {
      log.push(req.type === 'run' ? req.job : req.type);
      const data = structuredClone(req, { transfer });
      setTimeout(() => {
        if (opts.failOnLoad) {
          for (const l of listeners.error ?? []) l({ message: 'script failed to load' } as unknown as Event);
          return;
        }
        toHandlers?.({ data } as MessageEvent);
      }, 0);
    },
    addEventListener(type, listener) {
      (listeners[type] ??= []).push(listener);
    },
    terminate() {
      log.push('terminate');
    },
  };
  const crash = (message: string) => {
    for (const l of listeners.error ?? []) l({ message } as unknown as Event);
  };
  return Object.assign(w, { crash });
}

describe('exportAnimation (GIF)', () => {
  it('draws every frame letterboxed, and the GIF decodes to them with the frame rate and loop', async () => {
    const r = await exportAnimation(baseOptions(), noWorker);
    if (r.status !== 'done') throw new Error(`expected a file, got ${r.status}`);
    expect(r.blob.type).toBe('image/gif');
    const gif = await decode(r.blob);
    expect(gif.reader.numFrames()).toBe(36);
    expect([gif.reader.width, gif.reader.height]).toEqual([OUT.width, OUT.height]);
    expect(gif.reader.loopCount()).toBe(0);
    expect(gif.delays).toEqual(gifFrameDelaysCs(36, 24));
    for (const [k, f] of gif.frames.entries()) {
      // The bars keep the background; the view is grey; the marker sits where frame k puts it (scaled 0.9).
      expect(pixel(f, 2, 45)).toEqual([255, 255, 255]);
      expect(pixel(f, OUT.width - 3, 45)).toEqual([255, 255, 255]);
      expect(pixel(f, BAR_PX + 2, 2)).toEqual([0xdd, 0xdd, 0xdd]);
      const x = BAR_PX + Math.round(0.9 * (markerX(FRAMES[k]) + 5));
      expect(pixel(f, x, Math.round(0.9 * 45))).toEqual([0x10, 0x30, 0xc0]);
    }
  });

  it('plays once when loop is off', async () => {
    const r = await exportAnimation(baseOptions({ loop: false }), noWorker);
    if (r.status !== 'done') throw new Error(r.status);
    expect((await decode(r.blob)).reader.loopCount()).toBeNull();
  });

  it('reports progress from 0 to every frame, in order', async () => {
    const seen: ExportProgress[] = [];
    await exportAnimation(baseOptions({ onProgress: (p) => seen.push(p) }), noWorker);
    expect(seen[0]).toEqual({ framesDone: 0, frameCount: 36, fraction: 0 });
    expect(seen[seen.length - 1]).toEqual({ framesDone: 36, frameCount: 36, fraction: 1 });
    for (let i = 1; i < seen.length; i++) expect(seen[i].framesDone).toBe(seen[i - 1].framesDone + 1);
  });

  it('stops drawing and resolves cancelled when the signal aborts', async () => {
    const ac = new AbortController();
    let drawn = 0;
    const r = await exportAnimation(
      baseOptions({
        signal: ac.signal,
        renderFrame: (ctx, f, w, h) => {
          drawn++;
          drawMarker(ctx, f, w, h);
        },
        onProgress: (p) => {
          if (p.framesDone === 5) ac.abort();
        },
      }),
      noWorker,
    );
    expect(r).toEqual({ status: 'cancelled' });
    // The palette samples, 5 encoded frames and the FRAMES_IN_FLIGHT - 1 still waiting in the encoder when the
    // fifth came back; not one frame drawn after the abort.
    expect(drawn).toBeLessThanOrEqual(PALETTE_SAMPLE_FRAMES + 5 + FRAMES_IN_FLIGHT - 1);
  });

  it('resolves cancelled at once for a signal aborted before the start', async () => {
    const ac = new AbortController();
    ac.abort();
    expect(await exportAnimation(baseOptions({ signal: ac.signal }), noWorker)).toEqual({ status: 'cancelled' });
  });

  it('encodes in the worker when it loads, and terminates it at the end', async () => {
    const w = fakeWorker();
    const r = await exportAnimation(baseOptions(), { createSurface: createFakeSurface, createWorker: () => w });
    expect(r).toMatchObject({ status: 'done', encoder: 'worker' });
    expect(w.log.filter((t) => t === 'frame')).toHaveLength(36);
    expect(w.log.at(-1)).toBe('terminate');
  });

  it('falls back to the main thread when the worker script cannot load', async () => {
    const w = fakeWorker({ failOnLoad: true });
    const r = await exportAnimation(baseOptions(), { createSurface: createFakeSurface, createWorker: () => w });
    expect(r).toMatchObject({ status: 'done', encoder: 'main-thread' });
    if (r.status === 'done') expect((await decode(r.blob)).reader.numFrames()).toBe(36);
  });

  it('falls back to the main thread when the worker cannot even be constructed', async () => {
    const r = await exportAnimation(baseOptions(), {
      createSurface: createFakeSurface,
      createWorker: () => {
        throw new Error('SecurityError');
      },
    });
    expect(r).toMatchObject({ status: 'done', encoder: 'main-thread' });
  });

  it('never starts a second worker for one encode when the first dies mid-way (it held the encode)', async () => {
    let made = 0;
    const w = fakeWorker();
    const dying: WorkerLike = {
      ...w,
      postMessage(req, transfer) {
        // The worker crashes at the third frame: an error event, as an out-of-memory worker gives.
        if (req.type === 'run' && req.job === 'frame' && (req.params as { index: number }).index === 2)
          w.crash('out of memory');
        else w.postMessage(req, transfer);
      },
    };
    const r = exportAnimation(baseOptions(), {
      createSurface: createFakeSurface,
      createWorker: () => (made++ === 0 ? dying : fakeWorker()),
    });
    await expect(r).rejects.toThrow(/frame came before begin/);
    expect(made).toBe(1);
  });

  it('passes an encoder error on instead of retrying it elsewhere', async () => {
    const w = fakeWorker({ failWith: 'out of memory' });
    await expect(
      exportAnimation(baseOptions(), { createSurface: createFakeSurface, createWorker: () => w }),
    ).rejects.toThrow('out of memory');
    expect(w.log).toContain('terminate');
  });

  it('names options that are not an export', async () => {
    await expect(exportAnimation(baseOptions({ frames: [] }), noWorker)).rejects.toThrow(/frames.*got 0/);
    await expect(exportAnimation(baseOptions({ width: 0 }), noWorker)).rejects.toThrow(/width.*got 0/);
    await expect(exportAnimation(baseOptions({ height: 5000 }), noWorker)).rejects.toThrow(/height.*got 5000/);
    await expect(exportAnimation(baseOptions({ fps: 0 }), noWorker)).rejects.toThrow(/fps.*got 0/);
    await expect(exportAnimation(baseOptions({ fps: 61 }), noWorker)).rejects.toThrow(/fps.*got 61/);
  });
});

describe('exportAnimation (WebM)', () => {
  it('says unsupported, without throwing, where there is no MediaRecorder (Node)', async () => {
    const r = await exportAnimation(baseOptions({ format: 'webm' }), noWorker);
    expect(r.status).toBe('unsupported');
    if (r.status === 'unsupported') expect(r.reason).toMatch(/document|MediaRecorder/);
  });
});
