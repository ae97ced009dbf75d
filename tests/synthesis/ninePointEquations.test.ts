import { describe, expect, it } from 'vitest';
import { evaluate, rotation } from '../../src/synthesis/ninePoint/equations';
import { cognateRoots, orbit, orbitKey, sameKey, swapDyads } from '../../src/synthesis/ninePoint/group';
import { createRandom } from '../../src/synthesis/random';

type Pt = { x: number; y: number };

/**
 * A four-bar built by hand: ground pivots O2, O4, moving pivots A, B and coupler point P in the first pose; each later
 * pose turns the crank by φ, finds B on both circles (the branch that continues) and carries P rigidly with AB.
 */
function handLinkage(rand: () => number) {
  for (;;) {
    const O2 = { x: rand() * 2 - 1, y: rand() * 2 - 1 };
    const O4 = { x: rand() * 2 - 1, y: rand() * 2 - 1 };
    const A = { x: rand() * 2 - 1, y: rand() * 2 - 1 };
    const B = { x: rand() * 2 - 1, y: rand() * 2 - 1 };
    const P = { x: rand() * 2 - 1, y: rand() * 2 - 1 };
    const r2 = Math.hypot(A.x - O2.x, A.y - O2.y);
    const r3 = Math.hypot(B.x - A.x, B.y - A.y);
    const r4 = Math.hypot(B.x - O4.x, B.y - O4.y);
    const phi0 = Math.atan2(A.y - O2.y, A.x - O2.x);
    // P in the frame of A→B
    const t0 = Math.atan2(B.y - A.y, B.x - A.x);
    const lp = {
      u: (P.x - A.x) * Math.cos(t0) + (P.y - A.y) * Math.sin(t0),
      v: -(P.x - A.x) * Math.sin(t0) + (P.y - A.y) * Math.cos(t0),
    };
    const side = Math.sign((A.x - O4.x) * (B.y - O4.y) - (A.y - O4.y) * (B.x - O4.x));
    const points: Pt[] = [];
    const poses: { A: Pt; B: Pt }[] = [];
    for (let j = 0; j < 9; j++) {
      const phi = phi0 + 0.05 * j;
      const Aj = { x: O2.x + r2 * Math.cos(phi), y: O2.y + r2 * Math.sin(phi) };
      const dx = O4.x - Aj.x,
        dy = O4.y - Aj.y;
      const d = Math.hypot(dx, dy);
      const a = (r3 * r3 - r4 * r4 + d * d) / (2 * d);
      const h2 = r3 * r3 - a * a;
      if (!(h2 > 0)) break;
      const h = Math.sqrt(h2);
      const cands = [-1, 1].map((sg) => ({
        x: Aj.x + (a * dx) / d - (sg * h * dy) / d,
        y: Aj.y + (a * dy) / d + (sg * h * dx) / d,
      }));
      const Bj = cands.find((c) => Math.sign((Aj.x - O4.x) * (c.y - O4.y) - (Aj.y - O4.y) * (c.x - O4.x)) === side)!;
      const t = Math.atan2(Bj.y - Aj.y, Bj.x - Aj.x);
      points.push({
        x: Aj.x + lp.u * Math.cos(t) - lp.v * Math.sin(t),
        y: Aj.y + lp.u * Math.sin(t) + lp.v * Math.cos(t),
      });
      poses.push({ A: Aj, B: Bj });
    }
    if (points.length === 9) return { O2, O4, A, B, P, points, poses };
  }
}

/** Unknowns and parameters of the linkage, origin at the first coupler point, hats the conjugates. */
function encode(l: ReturnType<typeof handLinkage>) {
  const P0 = l.points[0];
  const c = (q: Pt): [number, number] => [q.x - P0.x, q.y - P0.y];
  const vals = [c(l.A), c(l.O2), c(l.B), c(l.O4)];
  const z = new Float64Array(16);
  vals.forEach(([re, im], k) => {
    z.set([re, im], 2 * k);
    z.set([re, -im], 8 + 2 * k);
  });
  const p = new Float64Array(32);
  for (let j = 1; j < 9; j++) {
    const [re, im] = c(l.points[j]);
    p.set([re, im], 2 * (j - 1));
    p.set([re, -im], 16 + 2 * (j - 1));
  }
  return { z, p };
}

function maxAbs(v: Float64Array): number {
  return v.reduce((m, x) => Math.max(m, Math.abs(x)), 0);
}

describe('nine-point equations', () => {
  const rand = createRandom(20261204);
  const l = handLinkage(rand);
  const { z, p } = encode(l);
  // Each E_j is a degree-7 polynomial in lengths of order 1: its terms are of order 1, so 1e-12 is
  // a few hundred ulps of cancellation at most.
  it('vanish at a linkage built by hand through its nine coupler points', () => {
    const F = new Float64Array(16);
    evaluate(z, p, F);
    expect(maxAbs(F)).toBeLessThan(1e-12);
  });

  it('do not vanish when a point is moved off the curve', () => {
    const F = new Float64Array(16);
    const q = p.slice();
    q[6] += 1e-3;
    q[22] += 1e-3;
    evaluate(z, q, F);
    expect(maxAbs(F)).toBeGreaterThan(1e-8);
  });

  it('give the coupler rotation of each pose', () => {
    const out = new Float64Array(2);
    const t0 = Math.atan2(l.B.y - l.A.y, l.B.x - l.A.x);
    for (let j = 1; j < 9; j++) {
      rotation(z, p, j - 1, out);
      const pose = l.poses[j];
      const t = Math.atan2(pose.B.y - pose.A.y, pose.B.x - pose.A.x);
      expect(out[0]).toBeCloseTo(Math.cos(t - t0), 10);
      expect(out[1]).toBeCloseTo(Math.sin(t - t0), 10);
    }
  });

  it('have the Jacobian of their finite differences (complex, holomorphic)', () => {
    const zc = new Float64Array(16);
    for (let i = 0; i < 16; i++) zc[i] = z[i] + 0.3 * (rand() - 0.5);
    const pc = new Float64Array(32);
    for (let i = 0; i < 32; i++) pc[i] = p[i] + 0.3 * (rand() - 0.5);
    const F = new Float64Array(16);
    const J = new Float64Array(128);
    const dp = new Float64Array(32);
    for (let i = 0; i < 32; i++) dp[i] = rand() - 0.5;
    const Fp = new Float64Array(16);
    evaluate(zc, pc, F, J, dp, Fp);
    const h = 1e-6;
    const Fa = new Float64Array(16);
    const Fb = new Float64Array(16);
    for (let k = 0; k < 8; k++) {
      const za = zc.slice();
      const zb = zc.slice();
      za[2 * k] += h;
      zb[2 * k] -= h;
      evaluate(za, pc, Fa);
      evaluate(zb, pc, Fb);
      for (let j = 0; j < 8; j++) {
        const scale = 1 + Math.abs(J[16 * j + 2 * k]) + Math.abs(J[16 * j + 2 * k + 1]);
        // central difference: error O(h²·F''') ≈ 1e-12 relative, rounding ε|F|/h ≈ 1e-10
        expect(Math.abs((Fa[2 * j] - Fb[2 * j]) / (2 * h) - J[16 * j + 2 * k]) / scale).toBeLessThan(1e-7);
        expect(Math.abs((Fa[2 * j + 1] - Fb[2 * j + 1]) / (2 * h) - J[16 * j + 2 * k + 1]) / scale).toBeLessThan(1e-7);
      }
    }
    const pa = pc.slice();
    const pb = pc.slice();
    for (let i = 0; i < 32; i++) {
      pa[i] += h * dp[i];
      pb[i] -= h * dp[i];
    }
    evaluate(zc, pa, Fa);
    evaluate(zc, pb, Fb);
    for (let i = 0; i < 16; i++) {
      expect(Math.abs((Fa[i] - Fb[i]) / (2 * h) - Fp[i]) / (1 + Math.abs(Fp[i]))).toBeLessThan(1e-7);
    }
  });

  it('hold at the relabelled root and at both Roberts cognates', () => {
    const F = new Float64Array(16);
    for (const w of [swapDyads(z), ...cognateRoots(z)]) {
      evaluate(w, p, F);
      expect(maxAbs(F)).toBeLessThan(1e-11);
    }
  });

  it('map the orbit to itself: six distinct roots sharing one key', () => {
    const o = orbit(z);
    const k0 = orbitKey(z);
    for (const w of o) expect(sameKey(orbitKey(w), k0, 1e-12)).toBe(true);
    for (let i = 0; i < 6; i++)
      for (let j = i + 1; j < 6; j++) expect(maxAbs(o[i].map((v, k) => v - o[j][k]))).toBeGreaterThan(1e-6);
    // the group closes: a cognate's cognates are already in the orbit
    for (const w of cognateRoots(o[1])) expect(o.some((u) => maxAbs(u.map((v, k) => v - w[k])) < 1e-10)).toBe(true);
  });
});
