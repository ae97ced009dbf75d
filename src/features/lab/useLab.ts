import { useCallback, useEffect, useRef, useState } from 'react';
import type { LabResult } from '../../study/workPrecision';
import type { Branch, Linkage } from '../../solver/types';
import type { JobRunner } from '../../shared/jobs/jobClient';
import type { LabJobs } from './jobs';

/** State of the solver lab's study: the last finished result, and progress while one runs. */
export interface LabStudy {
  result: LabResult | null;
  running: boolean;
  /** Fraction done in [0, 1] and the stage label, while running. */
  progress: { fraction: number; stage: string } | null;
  cancelled: boolean;
  error: string | null;
}

/** Wait after the last input change before a study starts (ms): dragging a slider does not start dozens. */
const DEBOUNCE_MS = 350;

/**
 * Runs the lab's work-precision study in the worker for the linkage, branch and step, again whenever
 * they change (debounced; a running study is cancelled first). run() starts it now, cancel() stops it;
 * the last finished result stays while a new one runs or after a cancel.
 */
export function useLab(
  client: JobRunner<LabJobs> | null,
  linkage: Linkage,
  branch: Branch,
  stepDeg: number,
): LabStudy & { run: () => void; cancel: () => void } {
  const [state, setState] = useState<LabStudy>({
    result: null,
    running: false,
    progress: null,
    cancelled: false,
    error: null,
  });
  // The running job; a newer run or an unmount replaces it, and answers of any other job are dropped.
  const jobRef = useRef<{ cancel: () => void } | null>(null);
  const { r1, r2, r3, r4 } = linkage;

  const cancel = useCallback(() => jobRef.current?.cancel(), []);

  const run = useCallback(() => {
    if (!client) return;
    jobRef.current?.cancel();
    setState((s) => ({ ...s, running: true, progress: { fraction: 0, stage: '' }, cancelled: false, error: null }));
    const token = { cancel: () => undefined as void };
    jobRef.current = token;
    const job = client.run(
      'lab',
      { linkage: { r1, r2, r3, r4 }, branch, stepDeg },
      {
        onProgress: (fraction, stage) => {
          if (jobRef.current === token) setState((s) => ({ ...s, progress: { fraction, stage } }));
        },
      },
    );
    token.cancel = job.cancel;
    const finish = (next: (s: LabStudy) => LabStudy) => {
      if (jobRef.current !== token) return;
      jobRef.current = null;
      setState(next);
    };
    job.result.then(
      (result) =>
        finish((s) =>
          result
            ? { result, running: false, progress: null, cancelled: false, error: null }
            : { ...s, running: false, progress: null, cancelled: true },
        ),
      (e: unknown) =>
        finish((s) => ({ ...s, running: false, progress: null, error: e instanceof Error ? e.message : String(e) })),
    );
  }, [client, r1, r2, r3, r4, branch, stepDeg]);

  useEffect(() => {
    const id = setTimeout(run, DEBOUNCE_MS);
    return () => clearTimeout(id);
  }, [run]);

  useEffect(() => () => jobRef.current?.cancel(), []);

  return { ...state, run, cancel };
}
