import { describe, expect, it } from 'vitest';
import type { Point } from '../../src/solver';
import {
  NINE_POINT_PATHS,
  mergeNinePoint,
  ninePointJumps,
  ninePointRefusal,
  ninePointSynthesis,
} from '../../src/synthesis';
import type { NinePointResult } from '../../src/synthesis';
import { robertsCognates } from '../../src/synthesis/cognates';
import { KNOWN, KNOWN_POINTS, KNOWN_THETA2, groundPivots, samePair, startIndexOf } from './ninePointFixtures';
import { sameKey } from '../../src/synthesis/ninePoint/group';
import { loadStartSystem } from '../../src/synthesis/ninePoint/ninePointSynthesis';
import { placedCouplerPoint } from '../../src/synthesis/placed';
import type { PlacedFourBar } from '../../src/synthesis/types';
import { WMS_PROBLEM_3 as PROBLEM_3 } from '../../src/features/synthesis/ninePoint/wmsProblem3';

describe('ninePointSynthesis', () => {
  it('refuses anything but nine finite, distinct points, naming the value', async () => {
    await expect(ninePointSynthesis(PROBLEM_3.slice(0, 8))).rejects.toThrow(
      /points must hold exactly 9 entries, got 8/,
    );
    await expect(ninePointSynthesis([...PROBLEM_3.slice(0, 8), { x: NaN, y: 0 }])).rejects.toThrow(/points\[8\]\.x/);
    await expect(ninePointSynthesis([...PROBLEM_3.slice(0, 8), { x: 1, y: Infinity }])).rejects.toThrow(
      /points\[8\]\.y/,
    );
    await expect(ninePointSynthesis('nine' as unknown as Point[])).rejects.toThrow(/points must be an array/);
    await expect(ninePointSynthesis([...PROBLEM_3.slice(0, 8), { ...PROBLEM_3[2] }])).rejects.toThrow(
      /points\[2\] and points\[8\] coincide/,
    );
  });

  it('refuses points on one line or one circle: the roots go to infinity', async () => {
    const line = Array.from({ length: 9 }, (_, k) => ({ x: 1 + 0.5 * k, y: 2 - 0.25 * k }));
    await expect(ninePointSynthesis(line)).rejects.toThrow(/one line.*infinity/);
    const circle = Array.from({ length: 9 }, (_, k) => ({
      x: 3 + 2 * Math.cos(0.6 * k),
      y: -1 + 2 * Math.sin(0.6 * k),
    }));
    await expect(ninePointSynthesis(circle)).rejects.toThrow(/one circle.*infinity/);
  });

  it('gives back a linkage built by hand and both its Roberts cognates from nine points of its curve', async () => {
    const i = await startIndexOf(KNOWN_POINTS, KNOWN, KNOWN_THETA2[0]);
    const r = await ninePointSynthesis(KNOWN_POINTS, { paths: { start: i, end: i + 1 } });
    expect(r.paths).toEqual({ total: 1, finished: 1, failed: 0, retracked: 0 });
    expect(r.classes.length).toBe(1);
    const got = r.classes[0].cognates;
    expect(got.length).toBe(3);
    // Oracle: the known design and the two cognates of src/synthesis/cognates (Roberts' diagram, built directly).
    const want = [KNOWN, ...robertsCognates(KNOWN, KNOWN_THETA2[0]).map((c) => c.design)].map(groundPivots);
    const tol = 1e-7;
    for (const w of want) expect(got.some((g) => samePair(groundPivots(g), w, tol))).toBe(true);
    const same = got.find((g) => samePair(groundPivots(g), want[0], tol))!;
    // Driven from either pivot: crank and rocker may swap, the coupler stays.
    const ends = (d: PlacedFourBar) => [d.links.r2, d.links.r4].sort((u, v) => u - v);
    expect(ends(same)[0]).toBeCloseTo(ends(KNOWN)[0], 8);
    expect(ends(same)[1]).toBeCloseTo(ends(KNOWN)[1], 8);
    expect(same.links.r3).toBeCloseTo(KNOWN.links.r3, 8);
    // The hand-built crank-rocker meets the points on one circuit, in order, within one turn.
    // Driven from its crank, the hand-built crank-rocker meets the points on one assembly, in order, within a turn.
    expect(same.links.r2).toBeCloseTo(KNOWN.links.r2, 8);
    expect(same.branches).toEqual(Array(9).fill(KNOWN.branch));
    const wrap = (t: number) => Math.atan2(Math.sin(t), Math.cos(t));
    same.theta2.forEach((t, k) => expect(wrap(t - KNOWN_THETA2[k])).toBeCloseTo(0, 8));
    for (const g of got) {
      for (let k = 0; k < 9; k++) {
        const q = placedCouplerPoint({ ...g, branch: g.branches[k] }, g.theta2[k])!;
        expect(Math.hypot(q.x - KNOWN_POINTS[k].x, q.y - KNOWN_POINTS[k].y)).toBeLessThan(1e-8);
      }
    }
    expect(r.classes[0].grashof).toBe(true);
    expect(r.classes[0].cognates[0]).toBe(same);
    expect(r.classes[0].defects).toEqual([]);
  });

  it('stops when cancelled, saying how many paths were not tracked', async () => {
    const r = await ninePointSynthesis(PROBLEM_3, { signal: { aborted: true } });
    expect(r.paths.total).toBe(1442);
    expect(r.paths.finished + r.paths.failed).toBe(0);
    expect(r.classes).toEqual([]);
  });

  it('reports progress over a slice of the start solutions', async () => {
    const seen: { done: number; total: number }[] = [];
    const r = await ninePointSynthesis(PROBLEM_3, {
      paths: { start: 100, end: 120 },
      onProgress: (p) => seen.push({ done: p.done, total: p.total }),
    });
    expect(r.paths.total).toBe(20);
    expect(r.paths.finished + r.paths.failed).toBe(20);
    expect(seen.at(-1)).toEqual({ done: 20, total: 20 });
    expect(seen.every((p, i) => i === 0 || p.done > seen[i - 1].done)).toBe(true);
  });

  it('ships as many start paths as NINE_POINT_PATHS says (the page deals them to its workers by that count)', async () => {
    expect((await loadStartSystem()).roots.length).toBe(NINE_POINT_PATHS);
  });

  it('words a refusal as data: the coinciding pair, a line, a circle; null for solvable points', () => {
    expect(ninePointRefusal(PROBLEM_3)).toBeNull();
    expect(ninePointRefusal([...PROBLEM_3.slice(0, 8), { ...PROBLEM_3[4] }])).toEqual({
      kind: 'coincide',
      i: 4,
      j: 8,
      point: PROBLEM_3[4],
    });
    expect(ninePointRefusal(Array.from({ length: 9 }, (_, k) => ({ x: k, y: 2 * k })))?.kind).toBe('line');
    const circle = Array.from({ length: 9 }, (_, k) => ({ x: Math.cos(k), y: Math.sin(k) }));
    expect(ninePointRefusal(circle)?.kind).toBe('circle');
  });

  it('keeps a class two slices both found once, counting the second path failed', async () => {
    const i = await startIndexOf(KNOWN_POINTS, KNOWN, KNOWN_THETA2[0]);
    const r = await ninePointSynthesis(KNOWN_POINTS, { paths: { start: i, end: i + 1 } });
    const other: NinePointResult = { classes: [], paths: { total: 2, finished: 2, failed: 0 } };
    // The same class again, its cognates listed in another order (the key is the set of ground pivots).
    const again: NinePointResult = {
      classes: [{ ...r.classes[0], cognates: [...r.classes[0].cognates].reverse() }],
      paths: { total: 1, finished: 1, failed: 0 },
    };
    const m = mergeNinePoint([r, other, again]);
    expect(m.classes.length).toBe(1);
    expect(m.paths).toEqual({ total: 4, finished: 3, failed: 1, retracked: 0 });
  });

  it('re-tracks a path that jumped onto a path of another slice, and counts it re-tracked', async () => {
    const i = await startIndexOf(KNOWN_POINTS, KNOWN, KNOWN_THETA2[0]);
    const j = i === 0 ? 1 : i - 1;
    const a = await ninePointSynthesis(KNOWN_POINTS, { paths: { start: i, end: i + 1 } });
    const b = await ninePointSynthesis(KNOWN_POINTS, { paths: { start: j, end: j + 1 } });
    expect(a.ends!.length).toBe(1);
    expect(sameKey(a.ends![0].key, b.ends![0].key, 1e-6)).toBe(false);
    // The injected jump: slice b's path j ends where slice a's path i does (the known linkage's orbit), its class too.
    const jumped: typeof b = {
      ...b,
      classes: a.classes.map((c) => ({ ...c, path: j })),
      ends: [{ path: j, key: a.ends![0].key }],
    };
    expect(ninePointJumps([a, jumped])).toEqual([Math.min(i, j), Math.max(i, j)]);
    // Merged as they are, the jump is said: one class, the second path failed.
    expect(mergeNinePoint([a, jumped]).paths).toEqual({ total: 2, finished: 1, failed: 1, retracked: 0 });
    const again = await ninePointSynthesis(KNOWN_POINTS, { retrack: ninePointJumps([a, jumped]) });
    expect(again.redone).toEqual([Math.min(i, j), Math.max(i, j)]);
    const m = mergeNinePoint([a, jumped, again]);
    expect(ninePointJumps([a, jumped, again])).toEqual([]);
    expect(m.paths).toEqual({ total: 2, finished: 2, failed: 0, retracked: 2 });
    // Path i still gives the known linkage's class, once; path j its own end again.
    expect(m.classes.filter((c) => c.path === i).length).toBe(1);
    expect(m.classes.filter((c) => c.path === j).length).toBe(b.classes.length);
    expect(m.ends!.map((e) => e.path).sort((x, y) => x - y)).toEqual([Math.min(i, j), Math.max(i, j)]);
    expect(sameKey(m.ends!.find((e) => e.path === j)!.key, b.ends![0].key, 1e-6)).toBe(true);
  });

  it('refuses a re-track of a path the start system does not have', async () => {
    await expect(ninePointSynthesis(KNOWN_POINTS, { retrack: [NINE_POINT_PATHS] })).rejects.toThrow(/retrack\[0\]/);
  });

  it('merges slices by summing paths and concatenating classes', () => {
    const a: NinePointResult = { classes: [], paths: { total: 3, finished: 2, failed: 1 } };
    const b: NinePointResult = { classes: [], paths: { total: 5, finished: 5, failed: 0 } };
    expect(mergeNinePoint([a, b]).paths).toEqual({ total: 8, finished: 7, failed: 1, retracked: 0 });
  });
});
