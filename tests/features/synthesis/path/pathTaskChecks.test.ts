import { describe, expect, it } from 'vitest';
import { missingTheta2, noneClose, pathTaskReasons } from '../../../../src/features/synthesis/path/pathTaskChecks';
import { DEFAULT_SYN_PATH } from '../../../../src/shared/state/slices/synthesisSlice';
import type { PathSolution, PathTask } from '../../../../src/synthesis';
import { oraclePoint } from '../../../synthesis/couplerOracle';

const three = [
  { x: 0, y: 0 },
  { x: 1, y: 0 },
  { x: 0, y: 1 },
];

/** A seeded generator (mulberry32): the random cases are the same on every run. */
function random(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

describe('missingTheta2', () => {
  it('names the first target without a given θ2, never taking a missing one as 0 (issue 34, 3)', () => {
    const s = { ...DEFAULT_SYN_PATH, targets: three, timing: 'given' as const };
    expect(missingTheta2({ ...s, givenTheta2Deg: [0, 30, 60] })).toBe(null);
    // A target added after the angles were given, and an emptied field.
    expect(missingTheta2({ ...s, givenTheta2Deg: [0, 30] })).toBe(3);
    expect(missingTheta2({ ...s, givenTheta2Deg: [0, NaN, 60] })).toBe(2);
    expect(missingTheta2({ ...s, givenTheta2Deg: [] })).toBe(1);
    // Other timings do not read the angles.
    expect(missingTheta2({ ...s, timing: 'free', givenTheta2Deg: [] })).toBe(null);
  });
});

describe('pathTaskReasons', () => {
  it('says links of at most 1 cannot reach targets 141 apart (the issue’s case)', () => {
    const task: PathTask = {
      targets: [
        { x: 0, y: 0 },
        { x: 100, y: 100 },
      ],
      timing: { kind: 'free' },
      bounds: { length: [0, 1], coupler: 1, pivot: { min: { x: -1, y: -1 }, max: { x: 1, y: 1 } } },
    };
    const reasons = pathTaskReasons(task);
    expect(reasons[0]).toEqual({ kind: 'span', reach: 2, span: Math.hypot(100, 100) });
    // T2 is 99·√2 from the box's corner (1, 1), beyond the reach 2.
    expect(reasons[1]).toMatchObject({ kind: 'pivot-far', target: 2, reach: 2 });
    expect(reasons[1].kind === 'pivot-far' && reasons[1].distance).toBeCloseTo(99 * Math.SQRT2, 12);
  });

  it('draws the span line at twice the longest link plus the coupler offset', () => {
    // |O2P| ≤ r2 + |AP| ≤ 1 + 1: two targets 4 apart are reachable from a pivot midway, 4.01 apart are not.
    const apart = (d: number): PathTask => ({
      targets: [
        { x: 0, y: 0 },
        { x: d, y: 0 },
      ],
      timing: { kind: 'free' },
      bounds: { length: [0, 1], coupler: 1, pivot: { min: { x: 1, y: -1 }, max: { x: 3, y: 1 } } },
    });
    expect(pathTaskReasons(apart(3.99))).toEqual([]);
    expect(pathTaskReasons(apart(4.01))).toEqual([{ kind: 'span', reach: 2, span: 4.01 }]);
  });

  it('names two targets at different places given one θ2, a whole turn apart too', () => {
    const at = (deg: number[]): PathTask => ({
      targets: three,
      timing: { kind: 'given', theta2: deg.map((d) => (d * Math.PI) / 180) },
    });
    expect(pathTaskReasons(at([10, 40, 70]))).toEqual([]);
    expect(pathTaskReasons(at([10, 40, 10]))).toEqual([{ kind: 'same-theta2', a: 1, b: 3, theta2: Math.PI / 18 }]);
    expect(pathTaskReasons(at([30, 390, 70]))[0]).toMatchObject({ kind: 'same-theta2', a: 1, b: 2 });
    // One place given twice at one angle is no contradiction.
    const twice: PathTask = { ...at([30, 30, 70]), targets: [three[0], three[0], three[2]] };
    expect(pathTaskReasons(twice)).toEqual([]);
  });

  it('never refuses a task a design in the bounds meets: targets on random designs’ coupler curves', () => {
    // Soundness against an independent 50-digit coupler point (tests/synthesis/couplerOracle.ts): 80 designs
    // with every link ≤ L, |AP| ≤ C and O2 in the box; the targets are their coupler points at given θ2.
    const rand = random(34);
    const L = 3;
    const C = 2;
    const box = { min: { x: -1, y: -2 }, max: { x: 2, y: 1 } };
    let tried = 0;
    for (let k = 0; k < 80; k++) {
      const [r1, r2, r3, r4] = [0, 0, 0, 0].map(() => 0.05 + (L - 0.05) * rand());
      const rho = C * rand();
      const phi = 2 * Math.PI * rand();
      const design = {
        r1,
        r2,
        r3,
        r4,
        u: rho * Math.cos(phi),
        v: rho * Math.sin(phi),
        O2x: box.min.x + (box.max.x - box.min.x) * rand(),
        O2y: box.min.y + (box.max.y - box.min.y) * rand(),
        g: 2 * Math.PI * rand(),
        sigma: (rand() < 0.5 ? 1 : -1) as 1 | -1,
      };
      const theta2: number[] = [];
      const targets: { x: number; y: number }[] = [];
      for (let i = 0; i < 24 && targets.length < 5; i++) {
        const th = (2 * Math.PI * i) / 24;
        const p = oraclePoint(design, th);
        if (p) {
          theta2.push(th);
          targets.push(p);
        }
      }
      if (targets.length < 2) continue;
      tried++;
      const task: PathTask = {
        targets,
        timing: { kind: 'given', theta2 },
        bounds: { length: [0, L], coupler: C, pivot: box },
      };
      expect(pathTaskReasons(task), JSON.stringify(design)).toEqual([]);
    }
    expect(tried).toBeGreaterThan(30);
  });
});

describe('noneClose', () => {
  const task: PathTask = { targets: three, timing: { kind: 'free' } };
  // The targets' size: the largest distance from their centroid (1/3, 1/3), √5 / 3.
  const size = Math.sqrt(5) / 3;
  const sol = (maxDistance: number) => ({ maxDistance }) as PathSolution;
  it('holds when no answer passes within 1 % of the targets’ size of every target, or there is none', () => {
    expect(noneClose(task, [])).toBe(true);
    expect(noneClose(task, [sol(0.0101 * size), sol(0.5)])).toBe(true);
    expect(noneClose(task, [sol(0.5), sol(0.0099 * size)])).toBe(false);
  });
});
