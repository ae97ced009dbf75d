import { useEffect, useState } from 'react';
import type { Branch, Linkage } from '../../solver/types';
import type { Messages } from '../i18n/messages';
import { benchMark } from './benchMarks';
import type { JobClient, JobClientMode, JobClientModeReason, JobRunner } from './jobClient';
import type { JobTable } from './jobTable';
import type { MethodChoice, TableJobs, TableResponse } from './protocol';

/** A job client made by create() once mounted and disposed on unmount, where it runs and why; null until mounted. */
export function useJobClient<T extends JobTable<T>>(
  create: (options: {
    onModeChange: (mode: JobClientMode, reason: JobClientModeReason | null, detail: string) => void;
  }) => JobClient<T>,
  name: string,
): { client: JobClient<T> | null; mode: JobClientMode; reason: JobClientModeReason | null } {
  const [client, setClient] = useState<JobClient<T> | null>(null);
  const [status, setStatus] = useState<{ mode: JobClientMode; reason: JobClientModeReason | null }>({
    mode: 'starting',
    reason: null,
  });
  useEffect(() => {
    const c = create({
      onModeChange: (mode, reason, detail) => {
        setStatus({ mode, reason });
        if (mode === 'restarted' || mode === 'main-thread') console.warn(`${name}: ${detail}; now ${mode}.`);
      },
    });
    setClient(c);
    setStatus({ mode: c.mode, reason: c.reason });
    return () => c.dispose();
  }, [create, name]);
  return { client, ...status };
}

/** The status line for a solver mode, or null when the first worker is (or is about to be) solving. */
export function solverStatusText(
  mode: JobClientMode,
  reason: JobClientModeReason | null,
  t: Pick<Messages, 'solvingOnMainThread' | 'solverRestarted' | 'solverStoppedTwice'>,
): string | null {
  if (mode === 'restarted') return t.solverRestarted;
  if (mode === 'main-thread') return reason === 'stopped' ? t.solverStoppedTwice : t.solvingOnMainThread;
  return null;
}

/** Wait after the last input change before the table is solved (ms): a drag solves only the view grid. */
const TABLE_DELAY_MS = 150;

/**
 * The whole samples + 1 table of a branch (the cycle summary's counts), solved once the inputs rest
 * and only while enabled; the last table stays meanwhile (check its linkage and samples). Latest wins.
 */
export function useCycleTable(
  client: JobRunner<TableJobs> | null,
  linkage: Linkage,
  samples: number,
  branch: Branch,
  solver: MethodChoice,
  enabled: boolean,
): TableResponse | null {
  const [table, setTable] = useState<TableResponse | null>(null);
  const { r1, r2, r3, r4 } = linkage;
  const { method, tol } = solver;
  useEffect(() => {
    if (!client || !enabled) return;
    const id = setTimeout(() => {
      client.run('table', { linkage: { r1, r2, r3, r4 }, samples, branch, solver: { method, tol } }).result.then(
        (r) => {
          if (!r) return;
          setTable(r);
          benchMark('fourbar:work:table', { ...r.work, elapsedMs: undefined });
        },
        (e: unknown) => console.warn(`Table solve failed: ${e instanceof Error ? e.message : String(e)}`),
      );
    }, TABLE_DELAY_MS);
    return () => clearTimeout(id);
  }, [client, enabled, r1, r2, r3, r4, samples, branch, method, tol]);
  return table;
}
