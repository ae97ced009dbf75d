import { useEffect, useLayoutEffect, useState } from 'react';
// The angles module alone: importing the barrel would pull the whole solver into the main bundle.
import { degToRad } from '../solver/angles';
import type { Branch, Linkage } from '../solver/types';
import type { CouplerPoint } from '../state/appState';
import type { SolverMode } from '../worker/client';
import { SolverClient } from '../worker/client';
import type { CycleResponse, MethodChoice, PointResponse, WorkCount } from '../worker/protocol';

/** The app's solver client (worker, or main-thread fallback) and where it solves; null until mounted. */
export function useSolverClient(): { client: SolverClient | null; mode: SolverMode } {
  const [client, setClient] = useState<SolverClient | null>(null);
  const [mode, setMode] = useState<SolverMode>('starting');
  useEffect(() => {
    const c = new SolverClient({
      onModeChange: (m, reason) => {
        setMode(m);
        if (m === 'main-thread') console.warn(`Solver: ${reason ?? 'no worker'}; solving on the main thread.`);
      },
    });
    setClient(c);
    setMode(c.mode);
    return () => c.dispose();
  }, []);
  return { client, mode };
}

/** What the visible views need from a cycle solve (anything not shown is not computed). */
export interface CycleNeeds {
  solver: MethodChoice;
  branch: Branch;
  /** The other branch is drawn (ghost, faint plot lines). */
  otherBranch: boolean;
  /** The coupler trace is drawn. */
  curves: boolean;
  /** Device-pixel width of the visible angle plots, 0 when none is visible. */
  plotPixels: number;
}

/** The latest solved cycle for these inputs (latest wins while they change), and the last error message. */
export function useCycle(
  client: SolverClient | null,
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
  const { otherBranch, curves, plotPixels } = needs;
  // A layout effect posts the request before the browser paints: a passive effect would wait a frame.
  useLayoutEffect(() => {
    if (!client) return;
    client
      .requestCycle({
        linkage: { r1, r2, r3, r4 },
        samples,
        coupler: { distance, angleRad: degToRad(angleDeg) },
        solver: { method, tol },
        branch,
        otherBranch,
        curves,
        plotPixels,
      })
      .then(
        (r) => {
          if (!r) return;
          setCycle(r);
          setError(null);
          markWork('cycle', r.work, r.elapsedMs);
        },
        (e: unknown) => setError(e instanceof Error ? e.message : String(e)),
      );
  }, [client, r1, r2, r3, r4, samples, distance, angleDeg, method, tol, branch, otherBranch, curves, plotPixels]);
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
  client: SolverClient | null,
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
      .requestPoint({
        linkage: { r1, r2, r3, r4 },
        branch,
        theta2Rad: degToRad(theta2Deg),
        stepRad: degToRad(360 / samples),
        coupler: { distance, angleRad: degToRad(angleDeg) },
        solver: { method, tol },
        ghost,
        newton,
      })
      .then(
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

/** Records the solver work of a response as a performance mark (read by npm run bench:ui). */
function markWork(kind: 'cycle' | 'point', work: WorkCount, elapsedMs?: number): void {
  if (typeof performance.mark === 'function')
    performance.mark(`fourbar:work:${kind}`, { detail: { ...work, elapsedMs } });
}
