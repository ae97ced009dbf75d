import { job } from '../../../shared/jobs/jobTable';

/** Start an encode: the size (px), whether it loops, and RGBA frames the global palette is computed from. */
export interface GifBeginParams {
  width: number;
  height: number;
  loop: boolean;
  samples: ArrayBuffer[];
}

/** Encode one frame (RGBA, width x height) shown for delayCs hundredths of a second. */
export interface GifFrameParams {
  index: number;
  rgba: ArrayBuffer;
  delayCs: number;
}

/** Finish the encode (no fields: the worker holds the encode). */
export type GifFinishParams = Record<string, never>;

/** Time allowed for one GIF call (ms): a palette or a large frame on a slow phone, with room to spare. */
export const GIF_CALL_MS = 30_000;

/**
 * The GIF encoder's jobs, run in order on one worker (it holds the encode between calls): every call is
 * answered (queue). A frame's pixels move to the worker; the palette samples are copied, so the main thread
 * can start again with them when the worker does not load.
 */
export const gifJobs = {
  /** Builds the palette; answers the colours in it. */
  begin: job<GifBeginParams, { colors: number }>({ mode: 'queue', budgetMs: () => GIF_CALL_MS }),
  /** Encodes a frame; answers its index. */
  frame: job<GifFrameParams, { index: number }>({
    mode: 'queue',
    budgetMs: () => GIF_CALL_MS,
    transfer: (p) => [p.rgba],
  }),
  /** Ends the file; answers its bytes (transferred). */
  finish: job<GifFinishParams, { bytes: ArrayBuffer }>({ mode: 'queue', budgetMs: () => GIF_CALL_MS }),
};

/** The GIF encoder's job table. */
export type GifJobs = typeof gifJobs;
