/**
 * Independent 50-digit oracle for a placed four-bar's coupler point, for the path-synthesis tests. Every double
 * input is taken as the exact binary value it holds (tests/oracle/reference.ts `exact`). The derivation differs
 * from src/synthesis/pathModel.ts on purpose: B is the intersection of the circles about A (radius r3) and O4
 * (radius r4), the branch picks the intersection left (open) or right (crossed) of the ray A→O4, and P is read in
 * the frame of AB. Derivatives are central differences at 50 digits (step 1e-18: truncation ~1e-36).
 */
import Decimal from 'decimal.js';
import { exact } from '../oracle/reference';

const D = Decimal.clone({ precision: 50, rounding: Decimal.ROUND_HALF_EVEN });
type Dec = InstanceType<typeof D>;

/** A design in the model's variables: lengths, coupler point (u along AB, v to its left), placement. */
export interface OracleDesign {
  r1: number;
  r2: number;
  r3: number;
  r4: number;
  u: number;
  v: number;
  O2x: number;
  O2y: number;
  g: number;
  /** +1 open, -1 crossed. */
  sigma: 1 | -1;
}

function dec(x: number | Dec): Dec {
  return typeof x === 'number' ? new D(exact(x).toString()) : x;
}

/** The coupler point in the design's own frame at θ2 (all Decimal), or null where the loop cannot close. */
function localPoint(v: Dec[], theta2: Dec, sigma: number): [Dec, Dec] | null {
  const [r1, r2, r3, r4, u, w] = v;
  const ax = r2.times(D.cos(theta2));
  const ay = r2.times(D.sin(theta2));
  const dx = r1.minus(ax);
  const dy = ay.neg();
  const s2 = dx.pow(2).plus(dy.pow(2));
  const s = s2.sqrt();
  const a = r3.pow(2).minus(r4.pow(2)).plus(s2).div(s.times(2));
  const h2 = r3.pow(2).minus(a.pow(2));
  if (h2.isNegative()) return null;
  const h = h2.sqrt().times(sigma);
  const bx = ax.plus(a.times(dx).div(s)).minus(h.times(dy).div(s));
  const by = ay.plus(a.times(dy).div(s)).plus(h.times(dx).div(s));
  const ex = bx.minus(ax).div(r3);
  const ey = by.minus(ay).div(r3);
  return [ax.plus(u.times(ex)).minus(w.times(ey)), ay.plus(u.times(ey)).plus(w.times(ex))];
}

/** The placed coupler point at θ2 (radians) as doubles, or null where it does not assemble. */
export function oraclePoint(d: OracleDesign, theta2: number): { x: number; y: number } | null {
  const v = [d.r1, d.r2, d.r3, d.r4, d.u, d.v].map(dec);
  const p = localPoint(v, dec(theta2), d.sigma);
  if (!p) return null;
  const g = dec(d.g);
  const c = D.cos(g);
  const s = D.sin(g);
  return {
    x: dec(d.O2x).plus(c.times(p[0])).minus(s.times(p[1])).toNumber(),
    y: dec(d.O2y).plus(s.times(p[0])).plus(c.times(p[1])).toNumber(),
  };
}

/** ∂P/∂(r1, r2, r3, r4, u, v, θ2) of the local coupler point by 50-digit central differences, as doubles. */
export function oracleLocalDerivatives(
  l: { r1: number; r2: number; r3: number; r4: number; u: number; v: number },
  theta2: number,
  sigma: 1 | -1,
): Array<[number, number]> {
  const base = [l.r1, l.r2, l.r3, l.r4, l.u, l.v, theta2].map(dec);
  const h = new D('1e-18');
  const out: Array<[number, number]> = [];
  for (let j = 0; j < 7; j++) {
    const plus = base.slice();
    const minus = base.slice();
    plus[j] = plus[j].plus(h);
    minus[j] = minus[j].minus(h);
    const p = localPoint(plus.slice(0, 6), plus[6], sigma);
    const q = localPoint(minus.slice(0, 6), minus[6], sigma);
    if (!p || !q) throw new Error('oracle: derivative taken too near a limit');
    out.push([p[0].minus(q[0]).div(h.times(2)).toNumber(), p[1].minus(q[1]).div(h.times(2)).toNumber()]);
  }
  return out;
}

/** The local coupler point (doubles) at θ2: for comparing the model's P itself. */
export function oracleLocalPoint(
  l: { r1: number; r2: number; r3: number; r4: number; u: number; v: number },
  theta2: number,
  sigma: 1 | -1,
): [number, number] | null {
  const p = localPoint([l.r1, l.r2, l.r3, l.r4, l.u, l.v].map(dec), dec(theta2), sigma);
  return p ? [p[0].toNumber(), p[1].toNumber()] : null;
}

/** Σd² of a placed design at the θ2 given (radians), by the 50-digit oracle; Infinity where it does not assemble. */
export function oracleError(
  design: {
    links: { r1: number; r2: number; r3: number; r4: number };
    branch: 'open' | 'crossed';
    O2: { x: number; y: number };
    groundAngle: number;
    pDist: number;
    pAngle: number;
  },
  theta2: number[],
  targets: { x: number; y: number }[],
): number {
  const od = {
    ...design.links,
    u: design.pDist * Math.cos(design.pAngle),
    v: design.pDist * Math.sin(design.pAngle),
    O2x: design.O2.x,
    O2y: design.O2.y,
    g: design.groundAngle,
    sigma: design.branch === 'open' ? (1 as const) : (-1 as const),
  };
  let sum: Dec = new D(0);
  for (let i = 0; i < targets.length; i++) {
    const p = oraclePoint(od, theta2[i]);
    if (!p) return Infinity;
    sum = sum.plus(new D(p.x).minus(targets[i].x).pow(2)).plus(new D(p.y).minus(targets[i].y).pow(2));
  }
  return sum.toNumber();
}
