import type { Branch, Linkage } from '../../solver/types';
import type { CouplerPoint } from './appState';

/** Identifiers of the built-in linkages. */
export type PresetId =
  | 'report'
  | 'dragLink'
  | 'doubleRocker'
  | 'tripleRocker'
  | 'parallelogram'
  | 'nearToggle'
  | 'chebyshevLambda'
  | 'hoeckens';

/** A built-in linkage: lengths (one unit), starting input angle (degrees), branch and coupler point. */
export interface Preset {
  id: PresetId;
  linkage: Linkage;
  theta2Deg: number;
  branch: Branch;
  coupler: CouplerPoint;
}

/**
 * The built-in linkages. Lengths of the double rocker, triple rocker, parallelogram and near-toggle
 * cases are from the project's hard-case table (cases 12, 10, 7 and 2); the straight-line linkages use
 * the classical proportions ground 2, crank 1, coupler 2.5, rocker 2.5 with P on the coupler line at
 * twice AB. Chebyshev's lambda is the Roberts cognate of Hoeckens' linkage: the same proportions on the
 * mirrored assembly, so the straight stretch runs along the top of its curve instead of the bottom.
 */
export const PRESETS: readonly Preset[] = [
  {
    id: 'report',
    linkage: { r1: 6, r2: 2, r3: 5, r4: 5 },
    theta2Deg: 45,
    branch: 'open',
    coupler: { distance: 2.5, angleDeg: 30 },
  },
  {
    id: 'dragLink',
    linkage: { r1: 2, r2: 4, r3: 4.5, r4: 5 },
    theta2Deg: 45,
    branch: 'open',
    coupler: { distance: 2, angleDeg: 40 },
  },
  {
    id: 'doubleRocker',
    linkage: { r1: 4, r2: 3, r3: 1, r4: 3.5 },
    theta2Deg: 60,
    branch: 'open',
    coupler: { distance: 1.5, angleDeg: 60 },
  },
  {
    id: 'tripleRocker',
    linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 },
    theta2Deg: 0,
    branch: 'open',
    coupler: { distance: 1.75, angleDeg: 30 },
  },
  {
    id: 'parallelogram',
    linkage: { r1: 4, r2: 2, r3: 4, r4: 2 },
    theta2Deg: 45,
    branch: 'open',
    coupler: { distance: 2, angleDeg: 45 },
  },
  {
    id: 'nearToggle',
    linkage: { r1: 4, r2: 1, r3: 3, r4: 2.000000001 },
    theta2Deg: 170,
    branch: 'open',
    coupler: { distance: 1.5, angleDeg: 20 },
  },
  {
    id: 'chebyshevLambda',
    linkage: { r1: 2, r2: 1, r3: 2.5, r4: 2.5 },
    theta2Deg: 0,
    branch: 'crossed',
    coupler: { distance: 5, angleDeg: 0 },
  },
  {
    id: 'hoeckens',
    linkage: { r1: 2, r2: 1, r3: 2.5, r4: 2.5 },
    theta2Deg: 0,
    branch: 'open',
    coupler: { distance: 5, angleDeg: 0 },
  },
];

/** The preset with this id; throws for an unknown id (a programmer error). */
export function getPreset(id: PresetId): Preset {
  const p = PRESETS.find((q) => q.id === id);
  if (!p) throw new Error(`unknown preset id ${JSON.stringify(id)}`);
  return p;
}

/**
 * The preset whose linkage and coupler point match exactly, or null. The branch picks between presets that
 * differ only by it (Hoeckens and Chebyshev's lambda); otherwise it does not matter, so choosing Crossed on a
 * preset keeps its name in the menu.
 */
export function matchPreset(linkage: Linkage, branch: Branch, coupler: CouplerPoint): PresetId | null {
  const same = PRESETS.filter((p) => {
    const l = p.linkage;
    return (
      l.r1 === linkage.r1 &&
      l.r2 === linkage.r2 &&
      l.r3 === linkage.r3 &&
      l.r4 === linkage.r4 &&
      p.coupler.distance === coupler.distance &&
      p.coupler.angleDeg === coupler.angleDeg
    );
  });
  return (same.find((p) => p.branch === branch) ?? same[0])?.id ?? null;
}
