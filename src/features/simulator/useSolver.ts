import { useLayoutEffect, useState } from 'react';
import { flushSync } from 'react-dom';
// The angles module alone: importing the barrel would pull the whole solver into the main bundle.
import { degToRad } from '../../solver/angles';
import type { Branch, Linkage } from '../../solver/types';
import type { CouplerPoint } from '../../shared/state/appState';
import { benchMark } from '../../shared/benchMarks';
import type { JobRunner } from '../../shared/jobs/jobClient';
import type { CycleResponse, MethodChoice, PointResponse, WorkCount } from '../../shared/solution';
import type { SimulatorJobs } from './jobs';

/**
 * What the visible views need from the worker's cycle solve (anything not shown is not computed). The plots are
 * solved on the main thread (usePlotSeries).
 */
export interface CycleNeeds {
  solver: MethodChoice;
  branch: Branch;
  /** The other branch is drawn (ghost, faint plot lines). */
  otherBranch: boolean;
  /** The coupler trace is drawn. */
  curves: boolean;
}

/**
 * The latest solved cycle (view resolution: NR statistics, coupler curves, classification) for these inputs (latest
 * wins while they change), and the last error.
 */
export function useCycle(
  client: JobRunner<SimulatorJobs> | null,
  linkage: Linkage,
  samples: number,
  coupler: CouplerPoint,
  needs: CycleNeeds,
): { cycle: CycleResponse | null; error: string | null } {
  const [cycle, setCycle] = useState<CycleResponse | null>(null);
  const [error, setError] = useState<string | null>(null);
  const { r1, r2, r3, r4 } = linkage;
  const { distance, angleDeg } = coupler;
  const { method, tol } = needs.solver;
  // With both branches wanted the branch choice does not change the request: no re-solve on a branch switch.
  const branch: Branch = needs.otherBranch ? 'open' : needs.branch;
  const { otherBranch, curves } = needs;
  // A layout effect posts the request before the browser paints: a passive effect would wait a frame.
  useLayoutEffect(() => {
    if (!client) return;
    client
      .run('cycle', {
        linkage: { r1, r2, r3, r4 },
        samples,
        coupler: { distance, angleRad: degToRad(angleDeg) },
        solver: { method, tol },
        branch,
        otherBranch,
        curves,
      })
      .result.then(
        (r) => {
          if (!r) return;
          // Drawn as soon as it arrives, not after a scheduler task: a drag's plots follow within a frame.
          flushSync(() => {
            setCycle(r);
            setError(null);
          });
          markWork('cycle', r.work, r.elapsedMs);
        },
        (e: unknown) => setError(e instanceof Error ? e.message : String(e)),
      );
  }, [client, r1, r2, r3, r4, samples, distance, angleDeg, method, tol, branch, otherBranch, curves]);
  return { cycle, error };
}

/** What the visible views need from a point solve. */
export interface PointNeeds {
  solver: MethodChoice;
  /** The other branch's pose is drawn (the ghost). */
  ghost: boolean;
  /** A panel shows the NR runs (numbers panel or convergence plot). */
  newton: boolean;
}

/** The latest solved pose at theta2 (degrees) on branch, with its NR runs (latest wins). */
export function usePoint(
  client: JobRunner<SimulatorJobs> | null,
  linkage: Linkage,
  branch: Branch,
  theta2Deg: number,
  samples: number,
  coupler: CouplerPoint,
  needs: PointNeeds,
): PointResponse | null {
  const [point, setPoint] = useState<PointResponse | null>(null);
  const { r1, r2, r3, r4 } = linkage;
  const { distance, angleDeg } = coupler;
  const { method, tol } = needs.solver;
  const { ghost, newton } = needs;
  useLayoutEffect(() => {
    if (!client) return;
    client
      .run('point', {
        linkage: { r1, r2, r3, r4 },
        branch,
        theta2Rad: degToRad(theta2Deg),
        stepRad: degToRad(360 / samples),
        coupler: { distance, angleRad: degToRad(angleDeg) },
        solver: { method, tol },
        ghost,
        newton,
      })
      .result.then(
        (r) => {
          if (!r) return;
          setPoint(r);
          markWork('point', r.work);
        },
        (e: unknown) => console.warn(`Point solve failed: ${e instanceof Error ? e.message : String(e)}`),
      );
  }, [client, r1, r2, r3, r4, branch, theta2Deg, samples, distance, angleDeg, method, tol, ghost, newton]);
  return point;
}

/** Records the solver work of an answer as a benchmark mark (read by npm run bench:ui; off in normal use). */
function markWork(kind: 'cycle' | 'point', work: WorkCount, elapsedMs?: number): void {
  benchMark(`fourbar:work:${kind}`, { ...work, elapsedMs });
}
