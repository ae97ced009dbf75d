import type { JobHandlers } from '../../../shared/jobs/jobTable';
import type { GifWriter } from './gifEncoder';
import { createGifWriter } from './gifEncoder';
import type { GifJobs } from './gifJobs';

/**
 * The handlers of one GIF encode (gifJobs): 'begin' builds the palette, each 'frame' is encoded at once,
 * 'finish' returns the file. The worker serves a session (gif.worker.ts), and so does the main-thread fallback.
 * A handler throws for a call out of order; the kit answers that as an error.
 */
export function createGifSession(): JobHandlers<GifJobs> {
  let writer: GifWriter | null = null;
  return {
    begin(p) {
      writer = createGifWriter({
        width: p.width,
        height: p.height,
        loop: p.loop,
        paletteSamples: p.samples.map((b) => new Uint8ClampedArray(b)),
      });
      return { colors: writer.colorCount };
    },
    frame(p) {
      if (!writer) throw new Error('a frame came before begin');
      writer.addFrame(new Uint8ClampedArray(p.rgba), p.delayCs);
      return { index: p.index };
    },
    finish() {
      if (!writer) throw new Error('finish came before begin');
      const bytes = writer.finish();
      writer = null;
      // A buffer of its own, exactly the file: it is transferred to the main thread.
      return { bytes: bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer };
    },
  };
}
