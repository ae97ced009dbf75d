import { radToDeg } from '../../solver/angles';
import type { Branch, Linkage } from '../../solver/types';

/** Identifiers of the 23 hard cases, in table order. */
export type HardCaseId =
  | 'reportCase'
  | 'toggle180'
  | 'toggle0'
  | 'changePoint'
  | 'justGrashof'
  | 'justNonGrashof'
  | 'parallelogram'
  | 'kiteOnPivot'
  | 'kiteFolded'
  | 'tripleRockerLimit'
  | 'tripleRockerGap'
  | 'doubleRocker'
  | 'limitAt90'
  | 'dragLinkFlat'
  | 'tinyCrank'
  | 'longLinks'
  | 'scaledUp'
  | 'scaledDown'
  | 'vanishingCrank'
  | 'tinyCoupler'
  | 'cannotAssemble'
  | 'singleAssembly'
  | 'singularStart';

/** A lab preset from the hard-case table: lengths (one unit), a telling input angle (degrees, [0, 360)) and branch. */
export interface HardCase {
  id: HardCaseId;
  /** Row number in the hard-case table, 1 to 23. */
  number: number;
  linkage: Linkage;
  theta2Deg: number;
  branch: Branch;
}

const CASE_1: Linkage = { r1: 6, r2: 2, r3: 5, r4: 5 };

/** Case 1 with every length multiplied by k (each product rounded once, as the tests' scaled cases are). */
function scaled(l: Linkage, k: number): Linkage {
  return { r1: l.r1 * k, r2: l.r2 * k, r3: l.r3 * k, r4: l.r4 * k };
}

/**
 * The hard cases as lab presets, numbered as in the project's hard-case table (lengths copied
 * exactly; nothing is read at run time). The angle is where the case bites: at or next to a limit,
 * toggle or change point. Case 17 is case 1 x 1e9, case 18 case 1 x 1e-12, and case 23 (a singular
 * NR start, guess theta3 = theta4) is case 1 at 45 degrees.
 */
export const HARD_CASES: readonly HardCase[] = [
  { id: 'reportCase', number: 1, linkage: CASE_1, theta2Deg: 90, branch: 'open' },
  { id: 'toggle180', number: 2, linkage: { r1: 4, r2: 1, r3: 3, r4: 2 + 1e-9 }, theta2Deg: 180, branch: 'open' },
  { id: 'toggle0', number: 3, linkage: { r1: 5, r2: 1, r3: 6, r4: 2 + 1e-9 }, theta2Deg: 0, branch: 'open' },
  { id: 'changePoint', number: 4, linkage: { r1: 4, r2: 1, r3: 3, r4: 2 }, theta2Deg: 180, branch: 'open' },
  { id: 'justGrashof', number: 5, linkage: { r1: 4, r2: 1, r3: 3, r4: 2 + 1e-12 }, theta2Deg: 180, branch: 'open' },
  // 180 itself is unreachable (limit 179.9999094034): start just inside, 1e-5 degrees from the limit.
  {
    id: 'justNonGrashof',
    number: 6,
    linkage: { r1: 4, r2: 1, r3: 3, r4: 2 - 1e-12 },
    theta2Deg: 179.9999,
    branch: 'open',
  },
  { id: 'parallelogram', number: 7, linkage: { r1: 4, r2: 2, r3: 4, r4: 2 }, theta2Deg: 90, branch: 'open' },
  { id: 'kiteOnPivot', number: 8, linkage: { r1: 2, r2: 2, r3: 4, r4: 4 }, theta2Deg: 0, branch: 'open' },
  // The crossed branch at 90 degrees is the folded one: theta4 = 180, theta3 = theta2 + 180.
  { id: 'kiteFolded', number: 9, linkage: { r1: 4, r2: 2, r3: 2, r4: 4 }, theta2Deg: 90, branch: 'crossed' },
  { id: 'tripleRockerLimit', number: 10, linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 }, theta2Deg: 135, branch: 'open' },
  { id: 'tripleRockerGap', number: 11, linkage: { r1: 3, r2: 2.5, r3: 4.2, r4: 1.5 }, theta2Deg: 60, branch: 'open' },
  { id: 'doubleRocker', number: 12, linkage: { r1: 4, r2: 3, r3: 1, r4: 3.5 }, theta2Deg: 60, branch: 'open' },
  { id: 'limitAt90', number: 13, linkage: { r1: 4, r2: 3, r3: 2.5, r4: 2.5 }, theta2Deg: 90, branch: 'open' },
  // pi/3 + 1e-8 rad in degrees; the crossed rocker is then within 2e-7 degrees of -180.
  {
    id: 'dragLinkFlat',
    number: 14,
    linkage: { r1: 1, r2: 2, r3: Math.sqrt(5.25), r4: 1.5 },
    theta2Deg: 60 + radToDeg(1e-8),
    branch: 'crossed',
  },
  { id: 'tinyCrank', number: 15, linkage: { r1: 1, r2: 1e-6, r3: 1, r4: 1 }, theta2Deg: 0, branch: 'open' },
  { id: 'longLinks', number: 16, linkage: { r1: 1e6, r2: 1, r3: 1e6 + 0.5, r4: 2 }, theta2Deg: 90, branch: 'open' },
  { id: 'scaledUp', number: 17, linkage: scaled(CASE_1, 1e9), theta2Deg: 90, branch: 'open' },
  { id: 'scaledDown', number: 18, linkage: scaled(CASE_1, 1e-12), theta2Deg: 90, branch: 'open' },
  { id: 'vanishingCrank', number: 19, linkage: { r1: 6, r2: 1e-300, r3: 5, r4: 5 }, theta2Deg: 45, branch: 'open' },
  { id: 'tinyCoupler', number: 20, linkage: { r1: 1, r2: 1, r3: 1e-9, r4: 1 }, theta2Deg: 60, branch: 'open' },
  { id: 'cannotAssemble', number: 21, linkage: { r1: 10, r2: 1, r3: 2, r4: 3 }, theta2Deg: 0, branch: 'open' },
  { id: 'singleAssembly', number: 22, linkage: { r1: 6, r2: 1, r3: 2, r4: 3 }, theta2Deg: 0, branch: 'open' },
  { id: 'singularStart', number: 23, linkage: CASE_1, theta2Deg: 45, branch: 'open' },
];
