import { expect } from 'vitest';
import type { Point } from '../../src/solver';
import { orbit, orbitKey, sameKey } from '../../src/synthesis/ninePoint/group';
import { loadStartSystem } from '../../src/synthesis/ninePoint/ninePointSynthesis';
import { Tracker } from '../../src/synthesis/ninePoint/tracker';
import { placedCouplerPoint, placedJoints } from '../../src/synthesis/placed';
import type { PlacedFourBar } from '../../src/synthesis/types';

/** A crank-rocker chosen by hand, and nine points of its coupler curve spread over most of a turn. */
export const KNOWN: PlacedFourBar = {
  links: { r1: 1, r2: 0.3, r3: 1.1, r4: 0.9 },
  branch: 'open',
  O2: { x: 0.2, y: -0.1 },
  groundAngle: 0.3,
  pDist: 0.6,
  pAngle: 0.7,
};
export const KNOWN_THETA2 = Array.from({ length: 9 }, (_, k) => 0.2 + 0.62 * k);
export const KNOWN_POINTS = KNOWN_THETA2.map((t) => placedCouplerPoint(KNOWN, t)!);

export const GAMMA = [0.8134, -0.5817];

export function groundPivots(d: PlacedFourBar): Point[] {
  return [d.O2, { x: d.O2.x + d.links.r1 * Math.cos(d.groundAngle), y: d.O2.y + d.links.r1 * Math.sin(d.groundAngle) }];
}
export const near = (p: Point, q: Point, tol: number) => Math.hypot(p.x - q.x, p.y - q.y) <= tol;
export function samePair(u: Point[], v: Point[], tol: number) {
  return (near(u[0], v[0], tol) && near(u[1], v[1], tol)) || (near(u[0], v[1], tol) && near(u[1], v[0], tol));
}

/**
 * The start solution whose path leads to the known linkage: its root at the nine points, tracked back along the
 * same homotopy (reversing s turns γ into 1/γ), matched to the shipped orbit representatives by orbit key.
 */
export async function startIndexOf(points: Point[], d: PlacedFourBar, theta2: number): Promise<number> {
  const j = placedJoints(d, theta2)!;
  const P0 = points[0];
  const size = Math.max(...points.map((q) => Math.hypot(q.x - P0.x, q.y - P0.y)));
  const z = new Float64Array(16);
  [j.A, j.O2, j.B, j.O4].forEach((q, k) => {
    z[2 * k] = (q.x - P0.x) / size;
    z[2 * k + 1] = (q.y - P0.y) / size;
    z[8 + 2 * k] = z[2 * k];
    z[9 + 2 * k] = -z[2 * k + 1];
  });
  const p = new Float64Array(32);
  for (let k = 1; k < 9; k++) {
    p[2 * (k - 1)] = (points[k].x - P0.x) / size;
    p[2 * (k - 1) + 1] = (points[k].y - P0.y) / size;
    p[16 + 2 * (k - 1)] = p[2 * (k - 1)];
    p[17 + 2 * (k - 1)] = -p[2 * (k - 1) + 1];
  }
  const start = await loadStartSystem();
  const m = GAMMA[0] ** 2 + GAMMA[1] ** 2;
  const t = new Tracker();
  t.setSegment(p, start.params, GAMMA[0] / m, -GAMMA[1] / m);
  expect(t.track(z).status).toBe('finished');
  const key = orbitKey(z);
  const hits = start.roots.map((r, i) => (sameKey(orbitKey(r), key, 1e-6) ? i : -1)).filter((i) => i >= 0);
  expect(hits.length).toBe(1);
  expect(
    orbit(start.roots[hits[0]]).some((w) => w.every((v, i) => Math.abs(v - z[i]) < 1e-6 * (1 + Math.abs(v)))),
  ).toBe(true);
  return hits[0];
}
