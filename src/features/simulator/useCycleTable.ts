import { useEffect, useState } from 'react';
import type { Branch, Linkage } from '../../solver/types';
import { benchMark } from '../../shared/benchMarks';
import type { JobRunner } from '../../shared/jobs/jobClient';
import type { MethodChoice, TableJobs, TableResponse } from '../../shared/solution';

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
