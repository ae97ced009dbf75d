import { robertsCognates } from '../../../synthesis/cognates';
import { sameDesign } from '../../../synthesis/pathScreen';
import type { PathSolution } from '../../../synthesis/types';
import type { CandidateFacts } from './candidateFacts';
import { candidateFacts, ranksLast } from './candidateFacts';

/** The answers in the order the page lists them, with their facts and, for each, the rank of a cognate listed above. */
export interface RankedCandidates {
  solutions: PathSolution[];
  facts: CandidateFacts[];
  /** For each answer, the rank (1-based) of an earlier answer it is a Roberts cognate of, or null. */
  cognateOf: (number | null)[];
}

/**
 * The answers as the page lists them (size: the targets' size, length unit): best Σd² first, except that
 * near-change-point and near-toggle designs come last (issue 34 item 2); each marked when it is a Roberts cognate
 * of one listed above it (the same linkage, by sameDesign, as one of that answer's two cognates).
 */
export function rankCandidates(solutions: readonly PathSolution[], size: number): RankedCandidates {
  const all = solutions.map((s) => ({ s, f: candidateFacts(s, size) }));
  const ranked = [...all.filter((c) => !ranksLast(c.f)), ...all.filter((c) => ranksLast(c.f))];
  const cognatesOf = ranked.map(({ s }) => {
    try {
      return robertsCognates(s.design, s.theta2[0] ?? 0).map((c) => c.design);
    } catch {
      // A coupler point at a pin has no cognates with positive links.
      return [];
    }
  });
  const cognateOf = ranked.map(({ s }, j) => {
    for (let i = 0; i < j; i++) if (cognatesOf[i].some((d) => sameDesign(d, s.design, size))) return i + 1;
    return null;
  });
  return { solutions: ranked.map((c) => c.s), facts: ranked.map((c) => c.f), cognateOf };
}
