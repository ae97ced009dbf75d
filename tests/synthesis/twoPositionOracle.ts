/**
 * A 40-digit oracle for two-position synthesis with a rocker output, independent of the construction in
 * src/synthesis/twoPosition.ts: the crank pivot O2 is searched on the ground circle |O2 − O4| = ground by its
 * direction φ, as a root of the signed angle ∠B1 O2 B2 = ±α (α = π(Q − 1)/(Q + 1)), bracketed in double precision
 * and bisected in decimal.js. A pivot is a design only when the extended and folded dead centres put the
 * coupler on the same assembly branch (B on the same side of the ray A→O4 in both).
 */
import Decimal from 'decimal.js';
import type { TwoPositionRockerTask } from '../../src/synthesis';

const D = Decimal.clone({ precision: 30 });
type P = { x: Decimal; y: Decimal };

export interface OracleRocker {
  O2: P;
  r2: Decimal;
  r3: Decimal;
}

export function oracleTwoPosition(task: TwoPositionRockerTask, samples = 720): OracleRocker[] {
  const Q = new D(task.timeRatio ?? 1);
  const pi = D.acos(-1);
  const alpha = pi.times(Q.minus(1)).div(Q.plus(1));
  const O4 = { x: new D(task.O4.x), y: new D(task.O4.y) };
  const r4 = new D(task.rocker);
  const g = new D(task.ground);
  const s = new D(task.startAngle);
  // Angles are measured from the start direction (cos s, sin s), so a start of 1e16 rad keeps every digit of φ.
  const cs = D.cos(s);
  const ss = D.sin(s);
  const at = (radius: Decimal, a: Decimal): P => {
    const c = D.cos(a);
    const n = D.sin(a);
    return {
      x: O4.x.plus(radius.times(cs.times(c).minus(ss.times(n)))),
      y: O4.y.plus(radius.times(ss.times(c).plus(cs.times(n)))),
    };
  };
  const B1 = at(r4, new D(0));
  const B2 = at(r4, new D(task.swing));
  const pivot = (phi: Decimal): P => at(g, phi);
  const signed = (O2: P): Decimal => {
    const ax = B1.x.minus(O2.x);
    const ay = B1.y.minus(O2.y);
    const bx = B2.x.minus(O2.x);
    const by = B2.y.minus(O2.y);
    return D.atan2(ax.times(by).minus(ay.times(bx)), ax.times(bx).plus(ay.times(by)));
  };
  // Brackets in double precision, in the rocker's frame (scale-free): the signed angle is smooth except where it
  // jumps by 2π (O2 inside the chord), which a bracket must not straddle.
  const hN = task.swing / 2;
  const gN = task.ground / task.rocker;
  const sN = (phi: number): number => {
    const x = gN * Math.cos(phi);
    const y = gN * Math.sin(phi);
    const ax = Math.cos(hN) - x;
    const ay = -Math.sin(hN) - y;
    const bx = Math.cos(hN) - x;
    const by = Math.sin(hN) - y;
    return Math.atan2(ax * by - ay * bx, ax * bx + ay * by);
  };
  const turn = (phiN: number): Decimal => new D(hN).plus(phiN); // frame angle → angle from the start
  const out: OracleRocker[] = [];
  const targets = alpha.isZero() ? [alpha] : [alpha, alpha.neg()];
  const aN = alpha.toNumber();
  for (const target of targets) {
    const tN = target.toNumber();
    for (let i = 0; i < samples; i++) {
      const p0 = (2 * Math.PI * i) / samples;
      const p1 = (2 * Math.PI * (i + 1)) / samples;
      const f0 = sN(p0) - tN;
      const f1 = sN(p1) - tN;
      if (Math.abs(sN(p1) - sN(p0)) > 1 || f0 === 0 || Math.sign(f0) === Math.sign(f1)) continue;
      // Illinois (regula falsi that halves the stale end's value): superlinear, and never leaves the bracket.
      const f = (phi: Decimal) => signed(pivot(phi)).minus(target);
      let lo = turn(p0);
      let hi = turn(p1);
      let fLo = f(lo);
      let fHi = f(hi);
      let root = lo;
      for (let k = 0, side = 0; k < 60; k++) {
        root = lo.minus(fLo.times(hi.minus(lo)).div(fHi.minus(fLo)));
        const fr = f(root);
        if (fr.abs().lt(1e-26)) break;
        if (fr.isNeg() === fLo.isNeg()) {
          lo = root;
          fLo = fr;
          if (side === -1) fHi = fHi.div(2);
          side = -1;
        } else {
          hi = root;
          fHi = fr;
          if (side === 1) fLo = fLo.div(2);
          side = 1;
        }
      }
      const O2 = pivot(root);
      if (
        signed(O2)
          .minus(target)
          .abs()
          .gt(1e-20 + 1e-20 * aN)
      )
        continue;
      const design = build(O2, B1, B2, O4);
      if (design) out.push(design);
    }
  }
  return out;
}

function build(O2: P, B1: P, B2: P, O4: P): OracleRocker | null {
  const dist = (a: P, b: P) => D.sqrt(a.x.minus(b.x).pow(2).plus(a.y.minus(b.y).pow(2)));
  const d1 = dist(O2, B1);
  const d2 = dist(O2, B2);
  const r2 = d1.minus(d2).abs().div(2);
  const r3 = d1.plus(d2).div(2);
  if (r2.isZero()) return null;
  const pin = (B: P, d: Decimal, extended: boolean): P => {
    const k = (extended ? r2 : r2.neg()).div(d);
    return { x: O2.x.plus(k.times(B.x.minus(O2.x))), y: O2.y.plus(k.times(B.y.minus(O2.y))) };
  };
  const side = (A: P, B: P) =>
    O4.x
      .minus(A.x)
      .times(B.y.minus(A.y))
      .minus(O4.y.minus(A.y).times(B.x.minus(A.x)))
      .isPos();
  const s1 = side(pin(B1, d1, d1.gt(d2)), B1);
  const s2 = side(pin(B2, d2, d2.gt(d1)), B2);
  return s1 === s2 ? { O2, r2, r3 } : null;
}
