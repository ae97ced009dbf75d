import type { GifWriter } from './gifEncoder';
import { createGifWriter } from './gifEncoder';
import type { GifWorkerRequest, GifWorkerResponse } from './gifProtocol';

/** An answer and the buffers to transfer with it. */
export interface GifAnswer {
  response: GifWorkerResponse;
  transfer: Transferable[];
}

/** One GIF encode driven by protocol messages; the worker and the main-thread fallback both run it. */
export interface GifSession {
  /** Answers a request; never throws (a failure is an 'error' answer). */
  handle(req: GifWorkerRequest): GifAnswer;
}

/** A fresh session: 'begin' builds the palette, each 'frame' is encoded at once, 'finish' returns the file. */
export function createGifSession(): GifSession {
  let writer: GifWriter | null = null;
  const answer = (response: GifWorkerResponse, transfer: Transferable[] = []): GifAnswer => ({ response, transfer });
  return {
    handle(req) {
      try {
        switch (req.type) {
          case 'begin':
            writer = createGifWriter({
              width: req.width,
              height: req.height,
              loop: req.loop,
              paletteSamples: req.samples.map((b) => new Uint8ClampedArray(b)),
            });
            return answer({ type: 'ready', colors: writer.colorCount });
          case 'frame':
            if (!writer) return answer({ type: 'error', message: 'a frame came before begin' });
            writer.addFrame(new Uint8ClampedArray(req.rgba), req.delayCs);
            return answer({ type: 'frame-done', index: req.index });
          case 'finish': {
            if (!writer) return answer({ type: 'error', message: 'finish came before begin' });
            const bytes = writer.finish();
            writer = null;
            const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer;
            return answer({ type: 'done', bytes: buffer }, [buffer]);
          }
          default:
            return answer({ type: 'error', message: `unknown request ${JSON.stringify(req)}` });
        }
      } catch (e) {
        return answer({ type: 'error', message: e instanceof Error ? e.message : String(e) });
      }
    },
  };
}
