import { classify } from '../../../solver/classify';
import type { NinePointClass, NinePointLinkage } from '../../../synthesis/ninePoint/ninePointSynthesis';
import type { CandidateFacts } from '../path/candidateFacts';
import { placedFourBarFacts } from '../path/candidateFacts';
import type { NineSort } from './ninePointMessages';

/** What the class list says about one class: each cognate's facts, and the class's size and input. */
export interface NineClassFacts {
  /** Facts of each cognate (as the Path mode's list shows a design), in the class's order. */
  cognates: CandidateFacts[];
  /** Longest link or coupler offset |AP| of each cognate (length unit). */
  sizes: number[];
  /** The smallest of sizes: the class fits a size bound when this does. */
  size: number;
  /** Some cognate is driven by a crank (its input turns fully). */
  crank: boolean;
  /** The best smallest transmission angle among the cognates (degrees; NaN when none assembles). */
  muMinDeg: number;
}

/** The design of a cognate as drawn and opened: the assembly it has at the first point. */
export function cognateDesign(d: NinePointLinkage): NinePointLinkage {
  return { ...d, branch: d.branches[0] ?? d.branch };
}

/** Longest link or coupler offset of a design (length unit). */
function sizeOf(d: NinePointLinkage): number {
  const { r1, r2, r3, r4 } = d.links;
  return Math.max(r1, r2, r3, r4, d.pDist);
}

/** The facts of one class through the nine points; size is the points' size (length unit). */
export function nineClassFacts(c: NinePointClass, size: number): NineClassFacts {
  const cognates = c.cognates.map((d) => placedFourBarFacts(cognateDesign(d), d.theta2[0] ?? 0, 0, size));
  const sizes = c.cognates.map(sizeOf);
  const mus = cognates.map((f) => f.muMinDeg).filter(Number.isFinite);
  return {
    cognates,
    sizes,
    size: Math.min(...sizes),
    crank: c.cognates.some((d) => classify(d.links).inputIsCrank),
    muMinDeg: mus.length > 0 ? Math.max(...mus) : NaN,
  };
}

/** The class list's filters: each true keeps only the classes that have it; maxSize null keeps every size. */
export interface NineFilters {
  grashof: boolean;
  crank: boolean;
  noDefect: boolean;
  maxSize: number | null;
  sort: NineSort;
}

/** No filter, in the order found. */
export const NO_FILTERS: NineFilters = { grashof: false, crank: false, noDefect: false, maxSize: null, sort: 'found' };

/**
 * The indices of the classes the filters keep, in the order asked: found (as the run found them), size (smallest
 * first) or transmission (best smallest transmission angle first; NaN last). 'No defect' means no circuit and no
 * order defect, as the issue asks; a branch defect alone is shown, not filtered.
 */
export function filterClasses(
  classes: readonly NinePointClass[],
  facts: readonly NineClassFacts[],
  f: NineFilters,
): number[] {
  const keep = classes
    .map((_, i) => i)
    .filter((i) => {
      const c = classes[i];
      if (f.grashof && !c.grashof) return false;
      if (f.crank && !facts[i].crank) return false;
      if (f.noDefect && (c.defects.includes('circuit') || c.defects.includes('order'))) return false;
      if (f.maxSize !== null && !(facts[i].size <= f.maxSize)) return false;
      return true;
    });
  if (f.sort === 'size') keep.sort((a, b) => facts[a].size - facts[b].size || a - b);
  if (f.sort === 'transmission') {
    const mu = (i: number) => (Number.isFinite(facts[i].muMinDeg) ? facts[i].muMinDeg : -Infinity);
    keep.sort((a, b) => mu(b) - mu(a) || a - b);
  }
  return keep;
}
