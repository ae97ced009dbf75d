import { drawFrame } from './frameSurface';
import type { AnimationExportResult, EncoderOptions } from './types';

/** Container and codecs tried in order: VP9, then VP8, then whatever WebM the browser picks. */
export const WEBM_MIME_TYPES = ['video/webm;codecs=vp9', 'video/webm;codecs=vp8', 'video/webm'] as const;

/** Whether this browser can record a canvas to WebM, and with which MIME type; otherwise why not. */
export type WebmSupport = { ok: true; mimeType: string } | { ok: false; reason: string };

/** Checks MediaRecorder, canvas.captureStream and a WebM MIME type, without recording anything. */
export function webmSupport(): WebmSupport {
  if (typeof document === 'undefined' || typeof HTMLCanvasElement === 'undefined') {
    return { ok: false, reason: 'no document to draw the video on' };
  }
  if (typeof MediaRecorder === 'undefined') return { ok: false, reason: 'this browser has no MediaRecorder' };
  if (typeof HTMLCanvasElement.prototype.captureStream !== 'function') {
    return { ok: false, reason: 'this browser cannot capture a canvas as a video stream' };
  }
  const mimeType = WEBM_MIME_TYPES.find((t) => MediaRecorder.isTypeSupported(t));
  if (!mimeType) return { ok: false, reason: 'this browser cannot record WebM video' };
  return { ok: true, mimeType };
}

/** Bit rate for a width x height video at fps: about 0.1 bit a pixel a frame, from 1 to 8 Mbit/s (flat line art). */
export function webmBitsPerSecond(width: number, height: number, fps: number): number {
  return Math.round(Math.min(8e6, Math.max(1e6, width * height * fps * 0.1)));
}

/** Resolves at performance time atMs, or at once when the signal aborts. */
function sleepUntil(atMs: number, signal?: AbortSignal): Promise<void> {
  return new Promise((resolve) => {
    const ms = atMs - performance.now();
    if (ms <= 0 || signal?.aborted) {
      resolve();
      return;
    }
    const done = () => {
      clearTimeout(id);
      signal?.removeEventListener('abort', done);
      resolve();
    };
    const id = setTimeout(done, ms);
    signal?.addEventListener('abort', done, { once: true });
  });
}

/**
 * Records the frames to WebM with MediaRecorder on canvas.captureStream(0): each frame is drawn once, in
 * order, and handed over with requestFrame(). MediaRecorder stamps a frame with the time it arrives, so the
 * frames are paced on a fixed timeline (frame k at k / fps seconds from the start) and the recording takes
 * as long as the animation plays. Resolves to unsupported (with the reason) where the browser cannot record,
 * cancelled once the signal aborts, else done with the video.
 */
export async function recordWebm(o: EncoderOptions): Promise<AnimationExportResult> {
  const support = webmSupport();
  if (!support.ok) return { status: 'unsupported', reason: support.reason };
  const { frames, width, height, signal } = o;
  if (signal?.aborted) return { status: 'cancelled' };
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const ctx = canvas.getContext('2d');
  if (!ctx) return { status: 'unsupported', reason: `no 2D context for a ${width}x${height} canvas` };
  const surface = { ctx, width, height };
  // Something must be on the canvas before the stream starts, or the first frame can be blank.
  await drawFrame(surface, frames[0], o);
  const stream = canvas.captureStream(0);
  const track = stream.getVideoTracks()[0] as CanvasCaptureMediaStreamTrack | undefined;
  if (!track || typeof track.requestFrame !== 'function') {
    stream.getTracks().forEach((t) => t.stop());
    return { status: 'unsupported', reason: 'this browser cannot request canvas frames one by one' };
  }
  let recorder: MediaRecorder;
  try {
    recorder = new MediaRecorder(stream, {
      mimeType: support.mimeType,
      videoBitsPerSecond: webmBitsPerSecond(width, height, o.fps),
    });
  } catch (e) {
    stream.getTracks().forEach((t) => t.stop());
    return { status: 'unsupported', reason: `MediaRecorder refused the stream: ${e instanceof Error ? e.message : e}` };
  }
  const chunks: Blob[] = [];
  let failure: string | null = null;
  recorder.addEventListener('dataavailable', (e) => {
    if (e.data.size > 0) chunks.push(e.data);
  });
  recorder.addEventListener('error', (e) => {
    failure = (e as ErrorEvent).message || 'MediaRecorder failed';
  });
  const stopped = new Promise<void>((resolve) => recorder.addEventListener('stop', () => resolve(), { once: true }));
  const started = new Promise<void>((resolve) => recorder.addEventListener('start', () => resolve(), { once: true }));
  const n = frames.length;
  const frameMs = 1000 / o.fps;
  let recorded = 0;
  try {
    recorder.start();
    // A recorder that fails to start goes straight to stop (after an error event).
    await Promise.race([started, stopped]);
    let t0 = performance.now();
    for (let k = 0; k < n && !signal?.aborted && failure === null && recorder.state === 'recording'; k++) {
      if (k > 0) await drawFrame(surface, frames[k], o);
      track.requestFrame();
      recorded = k + 1;
      o.onProgress?.({ framesDone: k + 1, frameCount: n, fraction: (k + 1) / n });
      // Frame k is shown until frame k + 1 arrives; the last one until the recording stops. A page that fell
      // behind (a busy machine) moves the timeline instead of sending frames in a burst the encoder would drop.
      const now = performance.now();
      if (t0 + (k + 1) * frameMs < now) t0 = now - (k + 0.5) * frameMs;
      await sleepUntil(t0 + (k + 1) * frameMs, signal);
    }
  } finally {
    if (recorder.state !== 'inactive') {
      recorder.stop();
      await stopped;
    }
    stream.getTracks().forEach((t) => t.stop());
  }
  if (signal?.aborted) return { status: 'cancelled' };
  if (failure !== null) throw new Error(failure);
  if (recorded < n) throw new Error(`MediaRecorder stopped after ${recorded} of ${n} frames`);
  return { status: 'done', blob: new Blob(chunks, { type: recorder.mimeType || support.mimeType }) };
}
