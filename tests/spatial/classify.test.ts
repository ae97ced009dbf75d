import { describe, expect, it } from 'vitest';
import { classifyRSSR, classifySpherical, solveRSSR, solveSpherical, sweepSpatial } from '../../src/spatial';
import type { InputRange } from '../../src/solver';
import type { SpatialModel } from '../../src/spatial';
import { closer } from './oracle';
import { seeded } from './random';

const TURN = 2 * Math.PI;
/** Whether t lies in the range (intervals may pass pi), and its distance to the nearest endpoint. */
function inRange(r: InputRange, t: number): { inside: boolean; margin: number } {
  if (r.full) return { inside: true, margin: Infinity };
  let inside = false;
  let margin = Infinity;
  for (const iv of r.intervals) {
    for (const s of [t - TURN, t, t + TURN]) {
      if (s >= iv.lo && s <= iv.hi) inside = true;
      margin = Math.min(margin, Math.abs(s - iv.lo), Math.abs(s - iv.hi));
    }
  }
  return { inside, margin };
}

/**
 * Whether the joint between arcs `ground` and `arm` turns fully, from first principles (test-side): the arc from the
 * arm's tip to the far pivot sweeps [|g - r|, min(g + r, 2 pi - g - r)] and the other two arcs f1, f2 span
 * [|f1 - f2|, min(f1 + f2, 2 pi - f1 - f2)].
 */
function jointTurns(ground: number, arm: number, f1: number, f2: number): boolean {
  const sweepLo = Math.abs(ground - arm);
  const sweepHi = Math.min(ground + arm, TURN - ground - arm);
  return Math.abs(f1 - f2) <= sweepLo && sweepHi <= Math.min(f1 + f2, TURN - f1 - f2);
}

describe('classifySpherical', () => {
  it('Grashof by the supplement rule exactly when some joint turns fully (2000 seeded arc sets)', () => {
    const rnd = seeded(90);
    for (let i = 0; i < 2000; i++) {
      const [a1, a2, a3, a4] = [0, 1, 2, 3].map(() => 0.02 + 3.1 * rnd());
      const turns =
        jointTurns(a1, a2, a3, a4) ||
        jointTurns(a2, a3, a4, a1) ||
        jointTurns(a3, a4, a1, a2) ||
        jointTurns(a4, a1, a2, a3);
      expect(classifySpherical({ a1, a2, a3, a4 }).grashof, `${[a1, a2, a3, a4]}`).toBe(turns);
    }
  });

  it('reaches theta2 exactly where the 50-digit oracle closes the loop, endpoints included (60 seeded linkages)', () => {
    const rnd = seeded(91);
    for (let i = 0; i < 60; i++) {
      const l = { a1: 0.1 + 2.9 * rnd(), a2: 0.1 + 2.9 * rnd(), a3: 0.1 + 2.9 * rnd(), a4: 0.1 + 2.9 * rnd() };
      const c = classifySpherical(l);
      const closes = closer('spherical', l);
      for (let k = 0; k < 48; k++) {
        const t = -Math.PI + (k + 0.37) * (TURN / 48);
        const { inside, margin } = inRange(c.inputRange, t);
        if (margin < 1e-9) continue;
        expect(inside, `${JSON.stringify(l)} at ${t}`).toBe(closes(t));
      }
      for (const iv of c.inputRange.full ? [] : c.inputRange.intervals) {
        expect(solveSpherical(l, iv.lo, 'open')).not.toBeNull();
        expect(solveSpherical(l, iv.hi, 'crossed')).not.toBeNull();
      }
      expect(c.type === 'cannot-assemble').toBe(c.inputRange.intervals.length === 0);
    }
  });

  it('types the presets of every class: crank-rocker, drag link, rocker-crank, double and triple rocker', () => {
    const d = (x: number) => (x * Math.PI) / 180;
    expect(classifySpherical({ a1: d(60), a2: d(20), a3: d(55), a4: d(45) }).type).toBe('crank-rocker');
    expect(classifySpherical({ a1: d(20), a2: d(45), a3: d(60), a4: d(50) }).type).toBe('double-crank');
    expect(classifySpherical({ a1: d(60), a2: d(45), a3: d(55), a4: d(20) }).type).toBe('rocker-crank');
    expect(classifySpherical({ a1: d(60), a2: d(45), a3: d(20), a4: d(55) }).type).toBe('double-rocker');
    expect(classifySpherical({ a1: d(40), a2: d(30), a3: d(35), a4: d(30) }).type).toBe('triple-rocker');
    expect(classifySpherical({ a1: d(100), a2: d(10), a3: d(20), a4: d(30) }).type).toBe('cannot-assemble');
    // Arcs over 90 degrees: an even number turn into supplements (the linkage with antipodal pins).
    const c = classifySpherical({ a1: d(60), a2: d(160), a3: d(125), a4: d(45) });
    expect(c.effectiveArcs!.map((x) => Math.round((x * 180) / Math.PI))).toEqual([60, 20, 55, 45]);
    expect(c.grashof).toBe(true);
    expect(classifySpherical({ a1: d(20), a2: d(40), a3: d(30), a4: d(30) }).changePoint).toBe(true);
  });
});

describe('classifyRSSR', () => {
  it('reaches theta2 exactly where the 50-digit oracle closes the loop (40 seeded skew linkages)', () => {
    const rnd = seeded(92);
    for (let i = 0; i < 40; i++) {
      const l = {
        r2: 0.3 + 2 * rnd(),
        r3: 0.5 + 4 * rnd(),
        r4: 0.3 + 2 * rnd(),
        a: 3 * rnd(),
        beta: 6 * rnd() - 3,
        h2: 2 * rnd() - 1,
        h4: 2 * rnd() - 1,
      };
      const c = classifyRSSR(l);
      const closes = closer('rssr', l);
      for (let k = 0; k < 48; k++) {
        const t = -Math.PI + (k + 0.37) * (TURN / 48);
        const { inside, margin } = inRange(c.inputRange, t);
        if (margin < 1e-9) continue;
        expect(inside, `${JSON.stringify(l)} at ${t}`).toBe(closes(t));
      }
      for (const iv of c.inputRange.full ? [] : c.inputRange.intervals) {
        expect(solveRSSR(l, iv.lo, 'open')).not.toBeNull();
        expect(solveRSSR(l, iv.hi, 'open')).not.toBeNull();
      }
    }
  });

  it('puts every output angle a sweep reaches inside the output range, and the sweeps touch its ends', () => {
    const models: SpatialModel[] = [
      { kind: 'rssr', linkage: { r2: 1, r3: 4, r4: 2, a: 3, beta: 1.0471975511965976, h2: 0.5, h4: 1 } },
      { kind: 'rssr', linkage: { r2: 3, r3: 3.5, r4: 3, a: 4, beta: 0.3, h2: 0.2, h4: 0 } },
      { kind: 'spherical', linkage: { a1: 1.05, a2: 0.35, a3: 0.96, a4: 0.79 } },
      { kind: 'spherical', linkage: { a1: 0.7, a2: 0.52, a3: 0.61, a4: 0.52 } },
    ];
    for (const m of models) {
      const c = m.kind === 'rssr' ? classifyRSSR(m.linkage) : classifySpherical(m.linkage);
      const outside: number[] = [];
      const ends = c.outputRange.full ? [] : c.outputRange.intervals.flatMap((iv) => [iv.lo, iv.hi]);
      const gaps = ends.map(() => Infinity);
      for (const branch of ['open', 'crossed'] as const) {
        const s = sweepSpatial(m, branch, { steps: 20000 });
        s.theta4.forEach((t4, i) => {
          if (!s.valid[i]) return;
          const r = inRange(c.outputRange, t4);
          if (!(r.inside || r.margin < 1e-12)) outside.push(t4);
          ends.forEach(
            (e, j) => (gaps[j] = Math.min(gaps[j], Math.abs(Math.atan2(Math.sin(t4 - e), Math.cos(t4 - e))))),
          );
        });
      }
      // 20000 steps of pi/1e4: an extreme at a dead centre is met to (step)^2, one at a fold (the input's limit) to
      // about sqrt(step) times the output's curvature there; 2e-3 rad holds both with room.
      expect(outside).toEqual([]);
      for (const g of gaps) expect(g).toBeLessThan(2e-3);
    }
  });
});
