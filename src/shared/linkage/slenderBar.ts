import type { LinkInertia } from '../../solver/forces';

/**
 * A uniform slender bar of length L (m) and mass per length rho (kg/m): m = rho L, I = m L² / 12 about its CG at
 * mid-link. The simulator's links and the mechanism page's link outlines are made of these.
 */
export function slenderBar(lengthM: number, rhoKgPerM: number): LinkInertia {
  const mass = rhoKgPerM * lengthM;
  return { mass, inertia: (mass * lengthM * lengthM) / 12, cg: { dist: lengthM / 2, angle: 0 } };
}
