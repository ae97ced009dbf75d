import type { GifencColor } from 'gifenc';
import { GIFEncoder, applyPalette, quantize } from 'gifenc';

/** Colours the global palette may hold: 255, since one of the 256 GIF slots marks "unchanged from the last frame". */
export const GIF_MAX_COLORS = 255;

/** Largest width or height a GIF can say (16-bit fields), pixels. */
export const GIF_MAX_SIDE_PX = 65535;

/** Options of createGifWriter: the size in pixels, loop forever or play once, and frames to take the palette from. */
export interface GifWriterOptions {
  width: number;
  height: number;
  /** true: loop forever (NETSCAPE2.0 loop count 0); false: play once (no loop extension). */
  loop: boolean;
  /** RGBA pixels (width · height · 4 bytes each) of a few frames spread over the cycle. */
  paletteSamples: readonly (Uint8Array | Uint8ClampedArray)[];
}

/** A GIF being written frame by frame. */
export interface GifWriter {
  /** Appends one frame of RGBA pixels shown for delayCs centiseconds. */
  addFrame(rgba: Uint8Array | Uint8ClampedArray, delayCs: number): void;
  /** Ends the stream and returns the whole GIF file. */
  finish(): Uint8Array;
  /** Frames written so far. */
  readonly frameCount: number;
  /** Colours in the global palette (without the "unchanged" slot). */
  readonly colorCount: number;
}

function checkSide(name: string, v: number): void {
  if (!Number.isInteger(v) || v < 1 || v > GIF_MAX_SIDE_PX) {
    throw new Error(`${name} must be an integer from 1 to ${GIF_MAX_SIDE_PX} pixels, got ${v}`);
  }
}

function checkPixels(name: string, rgba: Uint8Array | Uint8ClampedArray, width: number, height: number): void {
  if (rgba.length !== width * height * 4) {
    throw new Error(
      `${name} must hold ${width}x${height} RGBA pixels (${width * height * 4} bytes), got ${rgba.length}`,
    );
  }
}

/**
 * One palette for the whole animation from sample frames (gifenc's PNN quantiser over all their pixels).
 * The linkage drawing has few colours (background, grid, links, trace, anti-aliased edges between them),
 * so a global palette loses little and lets unchanged pixels be skipped from frame to frame.
 */
export function globalPalette(samples: readonly (Uint8Array | Uint8ClampedArray)[]): GifencColor[] {
  if (samples.length === 0) throw new Error('paletteSamples must hold at least one frame, got 0');
  const total = samples.reduce((s, f) => s + f.length, 0);
  const all = new Uint8Array(total);
  let off = 0;
  for (const f of samples) {
    all.set(f, off);
    off += f.length;
  }
  return quantize(all, GIF_MAX_COLORS);
}

/**
 * Starts a GIF of width x height pixels with one global palette. Every frame after the first keeps the last
 * frame (disposal 1) and marks the pixels whose palette index did not change as transparent, so the static
 * grid and trace cost next to nothing; the first frame is opaque, so a loop restarts cleanly.
 * Throws for a size outside 1..65535 or pixels of the wrong length.
 */
export function createGifWriter(options: GifWriterOptions): GifWriter {
  const { width, height, loop } = options;
  checkSide('width', width);
  checkSide('height', height);
  options.paletteSamples.forEach((s, i) => checkPixels(`paletteSamples[${i}]`, s, width, height));
  const palette = globalPalette(options.paletteSamples);
  const unchanged = palette.length;
  // The "unchanged" slot is never a pixel's nearest colour: applyPalette only sees the real palette.
  const table = [...palette, [255, 0, 255]];
  const gif = GIFEncoder();
  let previous: Uint8Array | null = null;
  let count = 0;
  return {
    addFrame(rgba, delayCs) {
      checkPixels(`frame ${count}`, rgba, width, height);
      if (!(delayCs >= 0) || !Number.isFinite(delayCs)) {
        throw new Error(`delayCs must be a non-negative number of centiseconds, got ${delayCs}`);
      }
      const index = applyPalette(rgba, palette);
      const delay = Math.round(delayCs) * 10;
      if (previous === null) {
        gif.writeFrame(index, width, height, { palette: table, delay, repeat: loop ? 0 : -1, dispose: 1 });
      } else {
        const out = new Uint8Array(index.length);
        for (let i = 0; i < index.length; i++) out[i] = index[i] === previous[i] ? unchanged : index[i];
        gif.writeFrame(out, width, height, { delay, transparent: true, transparentIndex: unchanged, dispose: 1 });
      }
      previous = index;
      count++;
    },
    finish() {
      if (count === 0) throw new Error('a GIF needs at least one frame, got 0');
      gif.finish();
      return gif.bytes();
    },
    get frameCount() {
      return count;
    },
    get colorCount() {
      return palette.length;
    },
  };
}
