import type { Point } from '../../../solver/kinematics';

/**
 * Problem 3 of Wampler, Morgan and Sommese (1992), as in the alphaCertified data of Hauenstein and Sottile: 64 real
 * linkage classes pass through these nine points. Data only (no imports at run time), so the page's example, the
 * tests, the e2e and the bench all read this one copy.
 */
export const WMS_PROBLEM_3: Point[] = [
  [0.25, 0.0],
  [0.52, 0.1],
  [0.8, 0.7],
  [1.2, 1.0],
  [1.4, 1.3],
  [1.1, 1.48],
  [0.7, 1.4],
  [0.2, 1.0],
  [0.02, 0.4],
].map(([x, y]) => ({ x, y }));
