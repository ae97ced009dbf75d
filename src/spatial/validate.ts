import { PI } from '../solver';
import type { RSSRLinkage, SpatialBranch, SpatialInput, SphericalLinkage } from './types';

/** A value as an error message shows it (strings quoted, objects by their JSON). */
export function describe(value: unknown): string {
  if (typeof value === 'string') return JSON.stringify(value);
  if (typeof value === 'number' || value === undefined || value === null) return String(value);
  try {
    return JSON.stringify(value) ?? String(value);
  } catch {
    return String(value);
  }
}

function isFiniteNumber(v: unknown): v is number {
  return typeof v === 'number' && Number.isFinite(v);
}

/** Throws unless value is a finite number; what says what the field is. */
export function checkFinite(field: string, value: unknown, what: string): void {
  if (!isFiniteNumber(value)) throw new Error(`${field} must be a finite ${what}, got ${describe(value)}`);
}

function checkArc(field: string, value: unknown): void {
  if (!isFiniteNumber(value) || !(value > 0 && value < PI)) {
    throw new Error(`${field} must be an arc in (0, pi) radians, got ${describe(value)}`);
  }
}

function checkLength(field: string, value: unknown, allowZero: boolean): void {
  if (!isFiniteNumber(value) || !(allowZero ? value >= 0 : value > 0)) {
    const what = allowZero ? 'a non-negative finite length' : 'a positive finite length';
    throw new Error(`${field} must be ${what}, got ${describe(value)}`);
  }
}

/** Throws an Error naming the field unless l is a spherical linkage (arcs in (0, pi), pDist in [0, pi]). */
export function validateSpherical(l: SphericalLinkage): void {
  if (typeof l !== 'object' || l === null) throw new Error(`linkage must be an object, got ${describe(l)}`);
  checkArc('a1', l.a1);
  checkArc('a2', l.a2);
  checkArc('a3', l.a3);
  checkArc('a4', l.a4);
  if (l.pDist !== undefined && (!isFiniteNumber(l.pDist) || l.pDist < 0 || l.pDist > PI)) {
    throw new Error(`pDist must be an arc in [0, pi] radians, got ${describe(l.pDist)}`);
  }
  if (l.pAngle !== undefined) checkFinite('pAngle', l.pAngle, 'angle in radians');
}

/** Throws an Error naming the field unless l is an RSSR linkage (r2, r3, r4 > 0, a >= 0, the rest finite). */
export function validateRSSR(l: RSSRLinkage): void {
  if (typeof l !== 'object' || l === null) throw new Error(`linkage must be an object, got ${describe(l)}`);
  checkLength('r2', l.r2, false);
  checkLength('r3', l.r3, false);
  checkLength('r4', l.r4, false);
  checkLength('a', l.a, true);
  checkFinite('beta', l.beta, 'angle in radians');
  checkFinite('h2', l.h2, 'length');
  checkFinite('h4', l.h4, 'length');
}

/** Throws unless branch is 'open' or 'crossed'; returns sigma, the sign of psi in theta4 = phi + sigma psi. */
export function branchSigma(branch: SpatialBranch): 1 | -1 {
  if (branch === 'open') return -1;
  if (branch === 'crossed') return 1;
  throw new Error(`branch must be 'open' or 'crossed', got ${describe(branch)}`);
}

/** Throws unless the input motion is absent or has finite omega2 and alpha2. */
export function validateInput(input: SpatialInput | undefined): void {
  if (input === undefined) return;
  if (typeof input !== 'object' || input === null) throw new Error(`input must be an object, got ${describe(input)}`);
  checkFinite('omega2', input.omega2, 'angular velocity in rad/s');
  checkFinite('alpha2', input.alpha2, 'angular acceleration in rad/s^2');
}
