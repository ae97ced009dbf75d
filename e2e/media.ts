import type { Page } from '@playwright/test';
import { GifReader } from 'omggif';

/** What a GIF file says: size, frames, loop count (0 forever, null once) and each frame's delay in centiseconds. */
export interface GifFacts {
  width: number;
  height: number;
  frames: number;
  loopCount: number | null;
  delaysCs: number[];
  bytes: number;
}

/** Decodes a GIF's structure with omggif (independent of the encoder) and decodes every frame's pixels. */
export function gifFacts(bytes: Uint8Array): GifFacts {
  const r = new GifReader(bytes);
  const pixels = new Uint8ClampedArray(r.width * r.height * 4);
  const delaysCs: number[] = [];
  for (let i = 0; i < r.numFrames(); i++) {
    r.decodeAndBlitFrameRGBA(i, pixels);
    delaysCs.push(r.frameInfo(i).delay);
  }
  return {
    width: r.width,
    height: r.height,
    frames: r.numFrames(),
    loopCount: r.loopCount(),
    delaysCs,
    bytes: bytes.length,
  };
}

/** What a WebM file says: its DocType, the Info Duration if written (seconds), frames and their time span. */
export interface WebmFacts {
  docType: string;
  /** Segment Info Duration in seconds; null when absent (MediaRecorder leaves it out). */
  durationSeconds: number | null;
  /** Video blocks (SimpleBlock or Block) found. */
  frames: number;
  /** Time of the last block minus the first, seconds. */
  spanSeconds: number;
  bytes: number;
}

// EBML master elements walked into (their size may be "unknown" in a recording): Segment, Info, Cluster, BlockGroup.
const MASTERS = new Set([0x18538067, 0x1549a966, 0x1f43b675, 0xa0]);

/** Reads an EBML variable-length integer at p: its value (marker bit removed unless keepMarker) and length. */
function vint(b: Uint8Array, p: number, keepMarker: boolean): { value: number; length: number; unknown: boolean } {
  const first = b[p];
  let length = 1;
  while (length <= 8 && !(first & (0x80 >> (length - 1)))) length++;
  if (length > 8) throw new Error(`bad EBML length byte 0x${first.toString(16)} at ${p}`);
  let value = keepMarker ? first : first & (0xff >> length);
  let allOnes = value === 0xff >> length;
  for (let i = 1; i < length; i++) {
    value = value * 256 + b[p + i];
    if (b[p + i] !== 0xff) allOnes = false;
  }
  return { value, length, unknown: !keepMarker && allOnes };
}

function uint(b: Uint8Array, p: number, n: number): number {
  let v = 0;
  for (let i = 0; i < n; i++) v = v * 256 + b[p + i];
  return v;
}

/**
 * Walks a WebM file's EBML (a flat scan that descends into Segment, Info, Cluster and BlockGroup whatever
 * their size says, so the unknown sizes of a live recording are fine) and reports its duration and frames.
 */
export function webmFacts(bytes: Uint8Array): WebmFacts {
  let p = 0;
  let docType = '';
  let scaleNs = 1_000_000;
  let duration: number | null = null;
  let cluster = 0;
  const times: number[] = [];
  const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  while (p < bytes.length) {
    const id = vint(bytes, p, true);
    const size = vint(bytes, p + id.length, false);
    const body = p + id.length + size.length;
    if (id.value === 0x1a45dfa3 || MASTERS.has(id.value)) {
      // EBML header is small and known-size: descend into it too, for DocType.
      p = body;
      continue;
    }
    const n = size.value;
    if (id.value === 0x4282) docType = new TextDecoder().decode(bytes.subarray(body, body + n));
    else if (id.value === 0x2ad7b1) scaleNs = uint(bytes, body, n);
    else if (id.value === 0x4489) duration = n === 4 ? dv.getFloat32(body) : dv.getFloat64(body);
    else if (id.value === 0xe7) cluster = uint(bytes, body, n);
    else if (id.value === 0xa3 || id.value === 0xa1) {
      const track = vint(bytes, body, false);
      times.push(cluster + dv.getInt16(body + track.length));
    }
    p = body + n;
  }
  const toSeconds = (ticks: number) => (ticks * scaleNs) / 1e9;
  return {
    docType,
    durationSeconds: duration === null ? null : toSeconds(duration),
    frames: times.length,
    spanSeconds: times.length > 1 ? toSeconds(Math.max(...times) - Math.min(...times)) : 0,
    bytes: bytes.length,
  };
}

/**
 * Duration in seconds that Chromium's <video> finds for a video file. A MediaRecorder WebM often says
 * Infinity until the end is known: then seek far past the end and wait for durationchange.
 */
export async function videoDurationInBrowser(page: Page, bytes: Uint8Array, mimeType: string): Promise<number> {
  return page.evaluate(
    async ({ b64, type }) => {
      const raw = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
      const url = URL.createObjectURL(new Blob([raw], { type }));
      const video = document.createElement('video');
      video.muted = true;
      video.preload = 'metadata';
      try {
        await new Promise<void>((resolve, reject) => {
          video.addEventListener('loadedmetadata', () => resolve(), { once: true });
          video.addEventListener('error', () => reject(new Error(`the video did not load: ${video.error?.message}`)), {
            once: true,
          });
          video.src = url;
        });
        if (Number.isFinite(video.duration)) return video.duration;
        await new Promise<void>((resolve) => {
          const done = () => {
            if (Number.isFinite(video.duration)) resolve();
          };
          video.addEventListener('durationchange', done);
          video.addEventListener('timeupdate', done);
          video.currentTime = 1e101;
        });
        return video.duration;
      } finally {
        URL.revokeObjectURL(url);
      }
    },
    { b64: Buffer.from(bytes).toString('base64'), type: mimeType },
  );
}
