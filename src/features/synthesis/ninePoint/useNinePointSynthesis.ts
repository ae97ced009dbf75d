import { useCallback, useEffect, useRef, useState } from 'react';
import type { Point } from '../../../solver/kinematics';
import type { NinePointResult } from '../../../synthesis/ninePoint/ninePointSynthesis';
import { NINE_POINT_PATHS, mergeNinePoint, ninePointJumps } from '../../../synthesis/ninePoint/ninePointSynthesis';
import type { SynthesisPool } from '../path/usePathSynthesis';

/** Start paths in one slice sent to a worker: small enough that Cancel loses little and the workers stay balanced. */
export const NINE_POINT_SLICE = 32;

/** Where a run is: not started, running, finished, cancelled (the classes found so far kept) or failed. */
export type NineRunStatus = 'idle' | 'running' | 'done' | 'cancelled' | 'failed';

/** A run's state: paths tracked so far and real roots seen, the result (merged slices), and what it took. */
export interface NineRunState {
  status: NineRunStatus;
  /** Paths tracked so far (finished, failed or in a slice under way) and real orbit ends seen so far. */
  progress: { done: number; total: number; real: number } | null;
  /** The merged result of every slice that finished; paths.total is always every start path. */
  result: NinePointResult | null;
  /** The points the result is for (kept while the targets are edited, until the next run). */
  points: Point[] | null;
  error: string | null;
  elapsedMs: number;
  workers: number;
}

const IDLE: NineRunState = {
  status: 'idle',
  progress: null,
  result: null,
  points: null,
  error: null,
  elapsedMs: 0,
  workers: 0,
};

/** The last run, kept across the page's unmounts (switching to the simulator and back). */
let lastRun: NineRunState = IDLE;

/** The slices [start, end) of the start paths, in order. */
export function nineSlices(total: number, size: number): { start: number; end: number }[] {
  const out: { start: number; end: number }[] = [];
  for (let s = 0; s < total; s += size) out.push({ start: s, end: Math.min(total, s + size) });
  return out;
}

/** The merged slices as a result over every start path: total is all paths, so the untracked ones show. */
export function nineResultOf(parts: NinePointResult[], total: number): NinePointResult {
  const m = mergeNinePoint(parts);
  return { classes: m.classes, paths: { ...m.paths, total } };
}

/**
 * Runs a nine-point synthesis on a pool of workers: the start paths dealt out in slices of NINE_POINT_SLICE, one slice
 * per worker at a time (a worker that finishes takes the next), the slices' results merged (mergeNinePoint). cancel()
 * stops every worker at once and keeps what the finished slices found (status 'cancelled', the rest counted as not
 * tracked). The pool is made on the first run (again after a cancel) and disposed with the page.
 */
export function useNinePointSynthesis(createPool: () => SynthesisPool) {
  const [state, setState] = useState<NineRunState>(lastRun);
  const pool = useRef<SynthesisPool | null>(null);
  const abort = useRef<AbortController | null>(null);
  const parts = useRef<NinePointResult[]>([]);

  useEffect(
    () => () => {
      abort.current?.abort();
      pool.current?.dispose();
      pool.current = null;
    },
    [],
  );

  const cancel = useCallback(() => {
    if (!abort.current) return;
    abort.current.abort();
    abort.current = null;
    // A worker sees the abort only between two paths: stop the workers outright; the next run makes a new pool.
    pool.current?.dispose();
    pool.current = null;
    setState((s) => {
      if (s.status !== 'running') return s;
      const next: NineRunState = {
        ...s,
        status: 'cancelled',
        progress: null,
        result: nineResultOf(parts.current, NINE_POINT_PATHS),
      };
      lastRun = next;
      return next;
    });
  }, []);

  const run = useCallback(
    async (points: Point[]) => {
      abort.current?.abort();
      const controller = new AbortController();
      abort.current = controller;
      if (!pool.current) pool.current = createPool();
      const p = pool.current;
      const start = performance.now();
      const slices = nineSlices(NINE_POINT_PATHS, NINE_POINT_SLICE);
      const done: NinePointResult[] = [];
      parts.current = done;
      // Paths of each slice under way so far, and real ends seen (by slice index).
      const inFlight = new Map<number, { done: number; real: number }>();
      const report = () => {
        if (controller.signal.aborted) return;
        let d = 0;
        let real = 0;
        for (const r of done) {
          d += r.paths.finished + r.paths.failed;
          real += r.classes.length;
        }
        for (const f of inFlight.values()) {
          d += f.done;
          real += f.real;
        }
        const progress = { done: d, total: NINE_POINT_PATHS, real };
        setState((s) => (s.status === 'running' ? { ...s, progress } : s));
      };
      setState((s) => ({
        ...s,
        status: 'running',
        progress: { done: 0, total: NINE_POINT_PATHS, real: 0 },
        result: null,
        points,
        error: null,
        workers: p.size,
      }));
      let next = 0;
      const worker = async (): Promise<void> => {
        while (next < slices.length && !controller.signal.aborted) {
          const k = next++;
          const { start: s, end: e } = slices[k];
          inFlight.set(k, { done: 0, real: 0 });
          const r = await p.run(
            'ninePointPart',
            { points, start: s, end: e },
            {
              signal: controller.signal,
              onProgress: (fraction, stage) => {
                inFlight.set(k, { done: Math.round(fraction * (e - s)), real: Number(stage) || 0 });
                report();
              },
            },
          ).result;
          inFlight.delete(k);
          if (r === null || controller.signal.aborted) return;
          done.push(r);
          report();
        }
      };
      try {
        await Promise.all(Array.from({ length: p.size }, worker));
        if (controller.signal.aborted) return;
        // A path that jumped onto a path of another slice shows only now: track those paths again, carefully.
        const jumps = ninePointJumps(done);
        if (jumps.length > 0) {
          const again = await p.run(
            'ninePointPart',
            { points, start: 0, end: 0, retrack: jumps },
            { signal: controller.signal },
          ).result;
          if (again === null || controller.signal.aborted) return;
          done.push(again);
        }
        const finished: NineRunState = {
          status: 'done',
          progress: null,
          result: nineResultOf(done, NINE_POINT_PATHS),
          points,
          error: null,
          elapsedMs: performance.now() - start,
          workers: p.size,
        };
        lastRun = finished;
        setState(finished);
      } catch (err) {
        if (controller.signal.aborted) return;
        controller.abort();
        setState((s) => ({
          ...s,
          status: 'failed',
          progress: null,
          result: null,
          error: err instanceof Error ? err.message : String(err),
        }));
      } finally {
        if (abort.current === controller) abort.current = null;
      }
    },
    [createPool],
  );

  return { ...state, run, cancel };
}
