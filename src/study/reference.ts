import Decimal from 'decimal.js';
import type { Angles, Linkage } from '../solver/types';

/** Significant digits of the lab's reference (double precision has about 16). */
export const REFERENCE_DIGITS = 40;

const D = Decimal.clone({ precision: REFERENCE_DIGITS, rounding: Decimal.ROUND_HALF_EVEN });
type Dec = InstanceType<typeof D>;
const PI = D.acos(-1);
const TWO_PI = PI.times(2);

/** The exact value of a finite double, from its binary expansion (a decimal string would round it). */
function exact(x: number): Dec {
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const bits = view.getBigUint64(0);
  const expBits = Number((bits >> 52n) & 0x7ffn);
  const frac = bits & 0xfffffffffffffn;
  const mant = expBits === 0 ? frac : frac | (1n << 52n);
  const e = (expBits === 0 ? 1 : expBits) - 1075;
  const v = new D(mant.toString()).times(new D(2).pow(e));
  return bits >> 63n ? v.neg() : v;
}

function wrap(a: Dec): number {
  let w = a.minus(TWO_PI.times(a.div(TWO_PI).floor()));
  if (w.greaterThan(PI)) w = w.minus(TWO_PI);
  return w.toNumber();
}

/**
 * Reference coupler and rocker angles (radians, wrapped to (-pi, pi]) at theta2 on branch sigma
 * (+1 open, -1 crossed), computed with 40-digit decimals taking the doubles as exact: law of
 * cosines in the triangle A, B, O4. Null when the loop cannot close or the pose is not unique.
 */
export function referencePose(l: Linkage, theta2: number, sigma: number): Angles | null {
  const r1 = exact(l.r1);
  const r2 = exact(l.r2);
  const r3 = exact(l.r3);
  const r4 = exact(l.r4);
  const t2 = exact(theta2);
  const c2 = D.cos(t2);
  const dx = r1.minus(r2.times(c2));
  const dy = r2.times(D.sin(t2)).neg();
  const s2 = dx.pow(2).plus(dy.pow(2));
  if (s2.isZero()) return null;
  const s = s2.sqrt();
  const cosA = r3.pow(2).plus(s2).minus(r4.pow(2)).div(r3.times(s).times(2));
  const cosO = r4.pow(2).plus(s2).minus(r3.pow(2)).div(r4.times(s).times(2));
  if (cosA.abs().greaterThan(1) || cosO.abs().greaterThan(1)) return null;
  const beta = D.atan2(dy, dx);
  const psi = D.acos(cosA);
  const gamma = D.acos(cosO);
  return {
    theta3: wrap(beta.plus(psi.times(sigma))),
    theta4: wrap(beta.plus(PI).minus(gamma.times(sigma))),
  };
}
