import { useEffect, useState } from 'react';
// The angles module alone: importing the barrel would pull the whole solver into the main bundle.
import { degToRad } from '../solver/angles';
import type { Branch, Linkage } from '../solver/types';
import type { CouplerPoint } from '../state/appState';
import type { SolverMode } from '../worker/client';
import { SolverClient } from '../worker/client';
import type { CycleResponse, PointResponse } from '../worker/protocol';

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

/** The latest solved cycle for these inputs (latest wins while they change), and the last error message. */
export function useCycle(
  client: SolverClient | null,
  linkage: Linkage,
  samples: number,
  coupler: CouplerPoint,
): { cycle: CycleResponse | null; error: string | null } {
  const [cycle, setCycle] = useState<CycleResponse | null>(null);
  const [error, setError] = useState<string | null>(null);
  const { r1, r2, r3, r4 } = linkage;
  const { distance, angleDeg } = coupler;
  useEffect(() => {
    if (!client) return;
    client
      .requestCycle({ linkage: { r1, r2, r3, r4 }, samples, coupler: { distance, angleRad: degToRad(angleDeg) } })
      .then(
        (r) => {
          if (!r) return;
          setCycle(r);
          setError(null);
        },
        (e: unknown) => setError(e instanceof Error ? e.message : String(e)),
      );
  }, [client, r1, r2, r3, r4, samples, distance, angleDeg]);
  return { cycle, error };
}

/** The latest solved pose at theta2 (degrees) on branch, with its NR runs (latest wins). */
export function usePoint(
  client: SolverClient | null,
  linkage: Linkage,
  branch: Branch,
  theta2Deg: number,
  samples: number,
  coupler: CouplerPoint,
): PointResponse | null {
  const [point, setPoint] = useState<PointResponse | null>(null);
  const { r1, r2, r3, r4 } = linkage;
  const { distance, angleDeg } = coupler;
  useEffect(() => {
    if (!client) return;
    client
      .requestPoint({
        linkage: { r1, r2, r3, r4 },
        branch,
        theta2Rad: degToRad(theta2Deg),
        stepRad: degToRad(360 / samples),
        coupler: { distance, angleRad: degToRad(angleDeg) },
      })
      .then(
        (r) => {
          if (r) setPoint(r);
        },
        (e: unknown) => console.warn(`Point solve failed: ${e instanceof Error ? e.message : String(e)}`),
      );
  }, [client, r1, r2, r3, r4, branch, theta2Deg, samples, distance, angleDeg]);
  return point;
}
