import { GifReader } from 'omggif';
import { describe, expect, it } from 'vitest';
import { createGifWriter } from '../../../../src/features/export/animation/gifEncoder';
import { gifFrameDelaysCs } from '../../../../src/features/export/animation/gifTiming';
import type { Raster, Rgb } from './raster';
import { couplerTrace, createRaster, drawLinkageFrame, fillRect } from './raster';

const W = 96;
const H = 54;
const WHITE: Rgb = [255, 255, 255];
const GREY: Rgb = [200, 200, 200];
const BLUE: Rgb = [20, 60, 220];
const RED: Rgb = [220, 30, 30];

/** Frame k of a flat test animation: white, a grey grid line, and a blue bar that moves right by 6 px a frame. */
function flatFrame(k: number): Raster {
  const r = createRaster(W, H, WHITE);
  fillRect(r, 0, 20, W, 1, GREY);
  fillRect(r, 4 + 6 * k, 10, 8, 30, BLUE);
  if (k % 3 === 0) fillRect(r, 80, 4, 6, 6, RED);
  return r;
}

/**
 * Decodes a GIF with omggif (an independent decoder) and composites its frames as a browser does with
 * disposal 1 (keep) or 0: each frame is drawn over the last, transparent pixels leave what was there.
 */
function decodeGif(bytes: Uint8Array) {
  const reader = new GifReader(bytes);
  const canvas = new Uint8ClampedArray(reader.width * reader.height * 4);
  const frames: Uint8ClampedArray[] = [];
  const info = [];
  for (let i = 0; i < reader.numFrames(); i++) {
    const f = reader.frameInfo(i);
    info.push(f);
    reader.decodeAndBlitFrameRGBA(i, canvas);
    frames.push(canvas.slice());
    if (f.disposal === 2 || f.disposal === 3) throw new Error(`frame ${i} asks for disposal ${f.disposal}`);
  }
  return { reader, frames, info };
}

/** Largest per-channel difference between two RGBA images (alpha ignored). */
function maxChannelError(a: Uint8ClampedArray, b: Uint8ClampedArray): number {
  let worst = 0;
  for (let i = 0; i < a.length; i += 4) {
    for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(a[i + c] - b[i + c]));
  }
  return worst;
}

describe('createGifWriter', () => {
  it('writes frames that an independent decoder reads back pixel for pixel, with their delays and loop', () => {
    const frames = Array.from({ length: 12 }, (_, k) => flatFrame(k));
    const delays = gifFrameDelaysCs(12, 30);
    const gif = createGifWriter({ width: W, height: H, loop: true, paletteSamples: [frames[0].data, frames[3].data] });
    frames.forEach((f, k) => gif.addFrame(f.data, delays[k]));
    const bytes = gif.finish();
    expect(String.fromCharCode(...bytes.subarray(0, 6))).toBe('GIF89a');
    const out = decodeGif(bytes);
    expect(out.reader.numFrames()).toBe(12);
    expect([out.reader.width, out.reader.height]).toEqual([W, H]);
    expect(out.reader.loopCount()).toBe(0);
    expect(out.info.map((f) => f.delay)).toEqual(delays);
    // Four colours, each alone in its RGB565 bin: the palette holds them exactly, so the frames round-trip.
    for (let k = 0; k < 12; k++) expect(maxChannelError(out.frames[k], frames[k].data)).toBe(0);
  });

  it('plays once when loop is off (no NETSCAPE2.0 loop extension)', () => {
    const frames = [flatFrame(0), flatFrame(1)];
    const gif = createGifWriter({ width: W, height: H, loop: false, paletteSamples: [frames[0].data] });
    for (const f of frames) gif.addFrame(f.data, 5);
    const out = decodeGif(gif.finish());
    expect(out.reader.numFrames()).toBe(2);
    expect(out.reader.loopCount()).toBeNull();
  });

  it('maps a colour missing from the sampled frames to its nearest palette colour', () => {
    // Red appears only in frames 0, 3, 6 and 9; sampling frame 1 alone leaves it out of the palette.
    const frames = [flatFrame(1), flatFrame(3)];
    const gif = createGifWriter({ width: W, height: H, loop: true, paletteSamples: [frames[0].data] });
    for (const f of frames) gif.addFrame(f.data, 5);
    const out = decodeGif(gif.finish());
    expect(maxChannelError(out.frames[0], frames[0].data)).toBe(0);
    const i = (6 * W + 82) * 4;
    expect([...out.frames[1].subarray(i, i + 3)]).not.toEqual([...RED]);
    expect(out.frames[1][i + 3]).toBe(255);
  });

  it('keeps anti-aliased linkage frames within a few levels per channel of the source', () => {
    const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
    const trace = couplerTrace(l, 'open', 90);
    const n = 8;
    const frames = Array.from({ length: n }, (_, k) =>
      drawLinkageFrame(160, 90, l, (2 * Math.PI * k) / n, 'open', trace),
    );
    const gif = createGifWriter({
      width: 160,
      height: 90,
      loop: true,
      paletteSamples: [frames[0].data, frames[4].data],
    });
    for (const f of frames) gif.addFrame(f.data, 4);
    const out = decodeGif(gif.finish());
    expect(out.reader.numFrames()).toBe(n);
    for (let k = 0; k < n; k++) {
      // Mean error: PNN over RGB565 keeps the flat colours exact and merges edge blends; 3 levels of 255 is
      // far below what a wrong palette or a misplaced frame would give (tens of levels over the moving links).
      let sum = 0;
      for (let i = 0; i < frames[k].data.length; i++) {
        if (i % 4 !== 3) sum += Math.abs(out.frames[k][i] - frames[k].data[i]);
      }
      expect(sum / ((frames[k].data.length * 3) / 4)).toBeLessThan(3);
    }
  });

  it('leaves unchanged pixels to the previous frame, so a small change costs few bytes', () => {
    const base = createRaster(W, H, WHITE);
    // A busy (pseudo-random) background: a full frame of it compresses poorly.
    let seed = 12345;
    for (let i = 0; i < W * H; i++) {
      seed = (Math.imul(seed, 1103515245) + 12345) >>> 0;
      if (seed >>> 31) fillRect(base, i % W, Math.floor(i / W), 1, 1, GREY);
    }
    const moved = createRaster(W, H, WHITE);
    moved.data.set(base.data);
    fillRect(moved, 40, 20, 4, 4, BLUE);
    const gif = createGifWriter({ width: W, height: H, loop: true, paletteSamples: [base.data, moved.data] });
    gif.addFrame(base.data, 5);
    gif.addFrame(moved.data, 5);
    gif.addFrame(base.data, 5);
    const out = decodeGif(gif.finish());
    expect(out.info[0].transparent_index).toBeNull();
    expect(out.info[1].transparent_index).not.toBeNull();
    expect(out.info[1].disposal).toBe(1);
    // Only 16 of 5184 pixels changed: the second frame's LZW data is a small fraction of the first's.
    expect(out.info[1].data_length).toBeLessThan(out.info[0].data_length / 5);
    expect(maxChannelError(out.frames[1], moved.data)).toBe(0);
    // Going back restores the pixels under the square.
    expect(maxChannelError(out.frames[2], base.data)).toBe(0);
  });

  it('names a wrong size and a frame of the wrong length', () => {
    const f = flatFrame(0);
    expect(() => createGifWriter({ width: 0, height: H, loop: true, paletteSamples: [f.data] })).toThrow(
      /width.*got 0/,
    );
    expect(() => createGifWriter({ width: W, height: 70000, loop: true, paletteSamples: [f.data] })).toThrow(
      /height.*got 70000/,
    );
    expect(() => createGifWriter({ width: W, height: H, loop: true, paletteSamples: [] })).toThrow(/at least one/);
    const gif = createGifWriter({ width: W, height: H, loop: true, paletteSamples: [f.data] });
    expect(() => gif.addFrame(new Uint8ClampedArray(10), 5)).toThrow(/frame 0 must hold 96x54 RGBA pixels.*got 10/);
    expect(() => gif.finish()).toThrow(/at least one frame/);
  });
});
