/**
 * Path generation: a four-bar whose coupler point passes through (or nearest to, in Σd²) given targets.
 * Method (docs/synthesis.md "Path generation"): rounds of random screening with closed-form placement
 * (globalSearch.ts), each start solved exactly by a bounded Levenberg–Marquardt method with analytic derivatives
 * (pathModel.ts, levenbergMarquardt.ts), then polishing and checking with the solver (pathScreen.ts).
 *
 * For a pool of workers: pathSynthesisPart runs the rounds part, part + parts, … of a seed's sequence and returns
 * plain candidates; mergePathCandidates merges the parts' candidates into answers. pathSynthesis is one part of one.
 */
import type { PathCandidate } from './globalSearch';
import { EXACT_F, runPathRound } from './globalSearch';
import { normaliseTask } from './pathTask';
import { screenCandidates } from './pathScreen';
import type { PathSolution, PathTask } from './types';
import { checkFiniteNumber, show } from './validate';

/** The part of an AbortSignal the search reads (the module's lib has no DOM types; a real AbortSignal fits). */
export interface AbortSignalLike {
  readonly aborted: boolean;
}

/** Options of pathSynthesis. */
export interface PathSynthesisOptions {
  /** Seed of the random stream (an integer; default 1). */
  seed?: number;
  /** Wall-clock budget in milliseconds (default 3000); the best so far is returned when it runs out. */
  budgetMs?: number;
  /** Aborting returns the best so far at the next check (every few tens of milliseconds). */
  signal?: AbortSignalLike;
  /** Called after each round and at the end: fraction of the work done (0 … 1) and the best Σd² so far. */
  onProgress?: (p: { fraction: number; best: number }) => void;
  /** Most rounds of the global stage (default 400); a run that ends by this or by an exact fit is reproducible. */
  rounds?: number;
}

/** Options of pathSynthesisPart: pathSynthesis's, plus which slice of the rounds this part runs. */
export interface PathSynthesisPartOptions extends PathSynthesisOptions {
  /** This part's index, 0 ≤ part < parts (default 0). */
  part?: number;
  /** Number of parts the rounds are dealt to (default 1). */
  parts?: number;
}

/** What one part found: its candidates (normalised, plain data), rounds run and work done. */
export interface PathSynthesisPartResult {
  candidates: PathCandidate[];
  rounds: number;
  evaluations: number;
}

/** Default wall-clock budget (ms). */
export const DEFAULT_BUDGET_MS = 3000;
/** Default cap on rounds. */
export const DEFAULT_ROUNDS = 400;
/** Rounds run before an exact fit may end the search (so a few exact designs can be offered). */
const MIN_ROUNDS_AFTER_EXACT = 2;
/** Candidates a part keeps (best first). */
const KEEP = 64;
/** Most time the final polish may take past the budget (ms). */
const MERGE_MS = 200;
/** Work between yields to the event loop (ms), so an abort posted from another thread is seen. */
const YIELD_MS = 25;

type Timers = { setTimeout(callback: () => void, ms: number): unknown };

function yieldToEventLoop(): Promise<void> {
  return new Promise((resolve) => (globalThis as unknown as Timers).setTimeout(resolve, 0));
}

function checkOptions(options: unknown): asserts options is PathSynthesisPartOptions {
  if (options === undefined) return;
  if (typeof options !== 'object' || options === null)
    throw new Error(`options must be an object, got ${show(options)}`);
  const o = options as Record<string, unknown>;
  if (o.seed !== undefined) checkFiniteNumber('options.seed', o.seed, 'integer');
  if (o.budgetMs !== undefined) {
    checkFiniteNumber('options.budgetMs', o.budgetMs, 'time in milliseconds');
    if (o.budgetMs < 0) throw new Error(`options.budgetMs must be >= 0 milliseconds, got ${o.budgetMs}`);
  }
  if (o.rounds !== undefined && !(Number.isInteger(o.rounds) && (o.rounds as number) >= 1)) {
    throw new Error(`options.rounds must be a positive integer, got ${show(o.rounds)}`);
  }
  if (o.onProgress !== undefined && typeof o.onProgress !== 'function') {
    throw new Error(`options.onProgress must be a function, got ${show(o.onProgress)}`);
  }
  if (o.signal !== undefined && (typeof o.signal !== 'object' || o.signal === null || !('aborted' in o.signal))) {
    throw new Error(`options.signal must be an AbortSignal, got ${show(o.signal)}`);
  }
  const parts = o.parts ?? 1;
  if (!(Number.isInteger(parts) && (parts as number) >= 1))
    throw new Error(`options.parts must be a positive integer, got ${show(o.parts)}`);
  const part = o.part ?? 0;
  if (!(Number.isInteger(part) && (part as number) >= 0 && (part as number) < (parts as number))) {
    throw new Error(
      `options.part must be an integer from 0 to parts - 1 (${(parts as number) - 1}), got ${show(o.part)}`,
    );
  }
}

/**
 * Runs this part's slice of the global stage (rounds part, part + parts, …, below options.rounds) and returns its
 * candidates. Deterministic for (task, seed, part, parts, rounds) when it ends by its own rule (the rounds or an
 * exact fit); a budget or an abort returns a prefix of the same work. Throws for a bad task or options.
 */
export async function pathSynthesisPart(
  task: PathTask,
  options: PathSynthesisPartOptions = {},
): Promise<PathSynthesisPartResult> {
  const t = normaliseTask(task);
  checkOptions(options);
  const seed = Math.trunc(options.seed ?? 1);
  const budgetMs = options.budgetMs ?? DEFAULT_BUDGET_MS;
  const maxRounds = options.rounds ?? DEFAULT_ROUNDS;
  const parts = options.parts ?? 1;
  const part = options.part ?? 0;
  const start = Date.now();
  const deadline = start + budgetMs;
  const scale2 = t.scale * t.scale;
  let candidates: PathCandidate[] = [];
  let evaluations = 0;
  let rounds = 0;
  let best = Infinity;
  let fraction = 0;
  let exactSince = -1;
  let lastYield = start;
  const myRounds = Math.ceil((maxRounds - part) / parts);
  for (let round = part; round < maxRounds; round += parts) {
    if (options.signal?.aborted || Date.now() >= deadline) break;
    const { candidates: found, stats } = runPathRound(t, seed, round, deadline);
    rounds++;
    evaluations += stats.evaluations;
    candidates = candidates.concat(found).sort((a, b) => a.f - b.f);
    if (candidates.length > KEEP) candidates.length = KEEP;
    if (candidates.length > 0) best = Math.min(best, candidates[0].f * scale2);
    fraction = Math.max(
      fraction,
      Math.min(1, rounds / myRounds, 1),
      Math.min(1, (Date.now() - start) / Math.max(1, budgetMs)),
    );
    options.onProgress?.({ fraction: Math.min(1, fraction), best });
    if (candidates.length > 0 && candidates[0].f <= EXACT_F) {
      if (exactSince < 0) exactSince = rounds;
      if (rounds - exactSince >= MIN_ROUNDS_AFTER_EXACT) break;
    }
    if (Date.now() - lastYield >= YIELD_MS) {
      await yieldToEventLoop();
      lastYield = Date.now();
    }
  }
  return { candidates, rounds, evaluations };
}

/**
 * Merges the candidates of one or more parts into checked, distinct answers, best first (at most 10); the polishing
 * stops at deadline (Date.now(), ms; default none, which makes the merge deterministic).
 */
export function mergePathCandidates(task: PathTask, parts: PathCandidate[][], deadline = Infinity): PathSolution[] {
  return screenCandidates(normaliseTask(task), task, parts, deadline);
}

/**
 * Path generation: up to 10 distinct four-bars whose coupler point passes nearest the targets (Σd², recomputed
 * from each design), best first; [] when nothing feasible was found. Options: seed (default 1), budgetMs
 * (default 3000), signal, onProgress, rounds (default 400). Throws an Error naming the value for a bad task or options.
 */
export async function pathSynthesis(task: PathTask, options: PathSynthesisOptions = {}): Promise<PathSolution[]> {
  const start = Date.now();
  const run = await pathSynthesisPart(task, { ...options, part: 0, parts: 1 });
  // The merge's polish gets a tenth of the budget (at most MERGE_MS) past it, or MERGE_MS after an abort.
  const budgetMs = options.budgetMs ?? DEFAULT_BUDGET_MS;
  const deadline = options.signal?.aborted
    ? Date.now() + MERGE_MS
    : Math.max(Date.now(), start + budgetMs) + Math.min(MERGE_MS, 0.1 * budgetMs);
  const solutions = mergePathCandidates(task, [run.candidates], options.rounds !== undefined ? Infinity : deadline);
  options.onProgress?.({ fraction: 1, best: Math.min(solutions[0]?.error ?? Infinity, bestOf(run, task)) });
  return solutions;
}

function bestOf(run: PathSynthesisPartResult, task: PathTask): number {
  const s = normaliseTask(task).scale;
  return run.candidates.length > 0 ? run.candidates[0].f * s * s : Infinity;
}
