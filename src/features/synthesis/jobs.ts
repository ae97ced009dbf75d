import type { PathCandidate } from '../../synthesis/globalSearch';
import type { PathProgress, PathSynthesisPartResult } from '../../synthesis/pathSynthesis';
import type { PathSolution, PathTask } from '../../synthesis/types';
import type { NinePointResult } from '../../synthesis/ninePoint/ninePointSynthesis';
import type { Point } from '../../solver/kinematics';
import { job } from '../../shared/jobs/jobTable';

/** One part of a path synthesis's global stage (pathSynthesisPart): rounds part, part + parts, … of a seed's run. */
export interface PathPartParams {
  task: PathTask;
  seed: number;
  part: number;
  parts: number;
  /** Most rounds of the whole run (all parts together); none (the page's runs): the budget governs. */
  rounds?: number;
  /** Wall-clock budget of the part (ms). */
  budgetMs: number;
}

/** The merge of the parts' candidates into checked answers (mergePathCandidates). */
export interface PathMergeParams {
  task: PathTask;
  parts: PathCandidate[][];
  /** Most time the polish may take, from the merge's start (ms); none: no deadline, so the merge is deterministic. */
  budgetMs?: number;
}

/** A slice [start, end) of the nine-point start paths, tracked to the nine points (ninePointSynthesis). */
export interface NinePointPartParams {
  points: Point[];
  start: number;
  end: number;
  /** Start paths to track again instead of the slice (ninePointJumps after the merge). */
  retrack?: number[];
}

/** Time allowed between two progress reports of a nine-point slice (ms): 16 paths on a slow phone, with room. */
export const NINE_POINT_PART_MS = 60_000;

/** Time allowed between two progress reports of a part (ms): one round on a slow phone, with room to spare. */
export const PATH_ROUND_MS = 30_000;
/** Time allowed for the merge (ms): the polish of 24 candidates on a slow phone. */
export const PATH_MERGE_MS = 60_000;

/**
 * The synthesis page's jobs, served by the solver worker. Both are queue jobs: a pool sends one part to each of its
 * workers at once; the page cancels a run through one AbortSignal. A part reports progress after each round, its
 * stage being the best Σd² so far and its best candidates so far, as JSON (pathStageText): a stopped run merges them.
 */
export const synthesisJobs = {
  pathPart: job<PathPartParams, PathSynthesisPartResult>({ mode: 'queue', budgetMs: () => PATH_ROUND_MS }),
  pathMerge: job<PathMergeParams, PathSolution[]>({ mode: 'queue', budgetMs: () => PATH_MERGE_MS }),
  ninePointPart: job<NinePointPartParams, NinePointResult>({ mode: 'queue', budgetMs: () => NINE_POINT_PART_MS }),
};

/** The synthesis page's job table. */
export type SynthesisJobs = typeof synthesisJobs;

/** A part's progress as its stage text: JSON of the best Σd² (null for none yet) and the candidates so far. */
export function pathStageText(p: PathProgress): string {
  return JSON.stringify({ best: Number.isFinite(p.best) ? p.best : null, candidates: p.candidates ?? [] });
}

/**
 * The best Σd² (Infinity for none) and candidates of a part's stage text; a bare number is a best alone, any other
 * text nothing found.
 */
export function readPathStage(stage: string): { best: number; candidates: PathCandidate[] } {
  try {
    const v = JSON.parse(stage) as unknown;
    if (typeof v === 'number') return { best: v, candidates: [] };
    if (typeof v !== 'object' || v === null) return { best: Infinity, candidates: [] };
    const o = v as { best?: unknown; candidates?: unknown };
    return {
      best: typeof o.best === 'number' ? o.best : Infinity,
      candidates: Array.isArray(o.candidates) ? (o.candidates as PathCandidate[]) : [],
    };
  } catch {
    return { best: Infinity, candidates: [] };
  }
}
