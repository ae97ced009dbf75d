import { useLayoutEffect, useMemo, useState } from 'react';
import { flushSync } from 'react-dom';
// The angles module alone: importing the barrel would pull the whole solver into the main bundle.
import { degToRad } from '../../solver/angles';
import type { Branch, Linkage } from '../../solver/types';
import type { CouplerPoint } from '../../shared/state/appState';
import { benchMark } from '../../shared/benchMarks';
import type { JobRunner } from '../../shared/jobs/jobClient';
import type { CycleResponse, MethodChoice, PointResponse, WorkCount } from '../../shared/solution';
import type { CycleParams, PointParams, SimulatorJobs } from './jobs';

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
 * The first answers solved on the main thread: each job's solve as the worker runs it. The first load draws its
 * first frame with them in the render that measures the page, instead of waiting for the worker's start and answers
 * and a render for each (the first load on a phone, docs/ARCHITECTURE.md); every later request goes to the worker.
 */
export interface FirstAnswers {
  cycle: (params: CycleParams) => CycleResponse;
  point: (params: PointParams) => PointResponse;
}

/**
 * The first request of a hook, solved at once on the main thread by solve (null: none). Stable while solve is:
 * first(params, answer) solves the hook's first request and hands the result to answer (true when it did);
 * answered(params) says whether params are that request, so it is not sent to the worker as well.
 */
function useFirstAnswer<P, R>(solve: ((params: P) => R) | null) {
  return useMemo(() => {
    // What this hook's first request was: whether it was tried, and its parameters' key once answered.
    const seen: { tried: boolean; key: string | null } = { tried: false, key: null };
    return {
      first(params: P, answer: (r: R) => void): boolean {
        if (!solve || seen.tried) return false;
        seen.tried = true;
        try {
          answer(solve(params));
          seen.key = JSON.stringify(params);
          return true;
        } catch {
          return false; // the worker answers it, with its error
        }
      },
      answered: (params: P): boolean => seen.key !== null && seen.key === JSON.stringify(params),
    };
  }, [solve]);
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
  firstSolve: FirstAnswers['cycle'] | null = null,
): { cycle: CycleResponse | null; error: string | null } {
  const [cycle, setCycle] = useState<CycleResponse | null>(null);
  const [error, setError] = useState<string | null>(null);
  const firstAnswer = useFirstAnswer(firstSolve);
  const { r1, r2, r3, r4 } = linkage;
  const { distance, angleDeg } = coupler;
  const { method, tol } = needs.solver;
  // With both branches wanted the branch choice does not change the request: no re-solve on a branch switch.
  const branch: Branch = needs.otherBranch ? 'open' : needs.branch;
  const { otherBranch, curves } = needs;
  // A layout effect posts the request before the browser paints: a passive effect would wait a frame.
  useLayoutEffect(() => {
    const params: CycleParams = {
      linkage: { r1, r2, r3, r4 },
      samples,
      coupler: { distance, angleRad: degToRad(angleDeg) },
      solver: { method, tol },
      branch,
      otherBranch,
      curves,
    };
    const answerNow = (r: CycleResponse) => {
      setCycle(r);
      markWork('cycle', r.work, r.elapsedMs);
    };
    if (firstAnswer.first(params, answerNow) || !client || firstAnswer.answered(params)) return;
    client.run('cycle', params).result.then(
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
  }, [client, firstAnswer, r1, r2, r3, r4, samples, distance, angleDeg, method, tol, branch, otherBranch, curves]);
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
  firstSolve: FirstAnswers['point'] | null = null,
): PointResponse | null {
  const [point, setPoint] = useState<PointResponse | null>(null);
  const firstAnswer = useFirstAnswer(firstSolve);
  const { r1, r2, r3, r4 } = linkage;
  const { distance, angleDeg } = coupler;
  const { method, tol } = needs.solver;
  const { ghost, newton } = needs;
  useLayoutEffect(() => {
    const params: PointParams = {
      linkage: { r1, r2, r3, r4 },
      branch,
      theta2Rad: degToRad(theta2Deg),
      stepRad: degToRad(360 / samples),
      coupler: { distance, angleRad: degToRad(angleDeg) },
      solver: { method, tol },
      ghost,
      newton,
    };
    const answerNow = (r: PointResponse) => {
      setPoint(r);
      markWork('point', r.work);
    };
    if (firstAnswer.first(params, answerNow) || !client || firstAnswer.answered(params)) return;
    client.run('point', params).result.then(
      (r) => {
        if (!r) return;
        setPoint(r);
        markWork('point', r.work);
      },
      (e: unknown) => console.warn(`Point solve failed: ${e instanceof Error ? e.message : String(e)}`),
    );
  }, [client, firstAnswer, r1, r2, r3, r4, branch, theta2Deg, samples, distance, angleDeg, method, tol, ghost, newton]);
  return point;
}

/** Records the solver work of an answer as a benchmark mark (read by npm run bench:ui; off in normal use). */
function markWork(kind: 'cycle' | 'point', work: WorkCount, elapsedMs?: number): void {
  benchMark(`fourbar:work:${kind}`, { ...work, elapsedMs });
}
