import { useMemo } from 'react';
import { robertsCognates } from '../../../synthesis/cognates';
import type { PlacedFourBar } from '../../../synthesis/types';
import { placedFourBarFacts } from './candidateFacts';
import type { DesignChoice } from './ChosenDesign';
import type { RankedCandidates } from './rankCandidates';
import { rankCandidates } from './rankCandidates';
import { targetsExtent } from './pathTaskOf';
import type { PathRunState } from './usePathSynthesis';

/** A linkage the chosen card offers, with the θ2 (radians) at which it passes the first target. */
export type TimedChoice = DesignChoice & { theta2: number };

/**
 * The answers as listed (rankCandidates), the candidate chosen and its cognates, each with the θ2 it passes the
 * first target at.
 */
export function usePathChoices(run: PathRunState, chosen: number): { choices: TimedChoice[] } & RankedCandidates {
  const size = targetsExtent(run.task?.targets ?? []).size;
  const ranked = useMemo(() => rankCandidates(run.solutions ?? [], size), [run.solutions, size]);
  const { solutions, facts } = ranked;
  const choices = useMemo(() => {
    const sol = solutions?.[chosen];
    if (!sol) return [];
    const first = { design: sol.design, facts: facts[chosen], theta2: sol.theta2[0] ?? 0 };
    let cognates: { design: PlacedFourBar; theta2: number }[] = [];
    try {
      cognates = robertsCognates(sol.design, first.theta2);
    } catch {
      // A coupler point at a pin has no cognates with positive links: offer the candidate alone.
    }
    return [
      first,
      ...cognates.map((c) => ({ ...c, facts: placedFourBarFacts(c.design, c.theta2, sol.maxDistance, size) })),
    ];
  }, [solutions, chosen, facts, size]);
  return { choices, ...ranked };
}
