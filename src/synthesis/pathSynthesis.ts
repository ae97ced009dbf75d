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
import { EXACT_F, pathRoundSteps } from './globalSearch';
import { pathLayout } from './pathProblem';
import { normaliseTask } from './pathTask';
import type { DesignKey } from './pathScreen';
import { designKey, sameKey, screenCandidates } from './pathScreen';
import type { PathSolution, PathTask } from './types';
import { checkFiniteNumber, show } from './validate';

/** The part of an AbortSignal the search reads (the module's lib has no DOM types; a real AbortSignal fits). */
export interface AbortSignalLike {
  readonly aborted: boolean;
}

/** Options of pathSynthesis. */
export interface PathSynthesisOptions {
  /** Seed of the random stream: an integer from 0 to 2³² − 1 (MAX_SEED; default 1). */
  seed?: number;
  /** Wall-clock budget in milliseconds (default 3000); the best so far is returned when it runs out. */
  budgetMs?: number;
  /** Aborting returns the best so far at the next check (every few tens of milliseconds). */
  signal?: AbortSignalLike;
  /**
   * Called after each round and at the end: fraction of the work done (0 … 1), the best Σd² so far and, from a part
   * after a round, its best candidates so far (at most PROGRESS_CANDIDATES, best first): a caller that stops the run
   * can merge them into answers (mergePathCandidates) instead of losing the work.
   */
  onProgress?: (p: PathProgress) => void;
  /**
   * Most rounds of the global stage (default: no cap, the search goes on while the budget lasts); a run that ends by
   * this or by an exact fit is reproducible, one that ends by the budget is a prefix of the same rounds.
   */
  rounds?: number;
}

/** A progress report of pathSynthesis and pathSynthesisPart (see PathSynthesisOptions.onProgress). */
export interface PathProgress {
  fraction: number;
  best: number;
  candidates?: PathCandidate[];
}

/** Candidates a part's progress report carries: enough to merge into ten answers after a stop. */
export const PROGRESS_CANDIDATES = 24;

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
  /** True when the part ended by its own rule (its rounds, or an exact fit), not by the budget or an abort. */
  complete: boolean;
}

/** Largest seed (seeds are 32-bit: 1 and 1 + 2³² would draw the same numbers, so larger ones are refused). */
export const MAX_SEED = 2 ** 32 - 1;

/** Default wall-clock budget (ms). */
export const DEFAULT_BUDGET_MS = 3000;
/** Default cap on rounds: none, so that a run keeps searching while its budget lasts (issue 34 item 6). */
export const DEFAULT_ROUNDS = Infinity;
/** Rounds run before an exact fit may end the search (so a few exact designs can be offered). */
const MIN_ROUNDS_AFTER_EXACT = 2;
/** Candidates the merge keeps from the rounds it counts (best first). */
const KEEP = 64;
/** Candidates a part keeps (best first): every one up to 400 rounds of 4 starts; beyond, the best. */
const PART_KEEP = 4096;
/** Share of pathSynthesis's budget kept for the final polish (the global stage stops before it). */
export const POLISH_SHARE = 0.1;
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
  if (
    o.seed !== undefined &&
    !(Number.isInteger(o.seed) && (o.seed as number) >= 0 && (o.seed as number) <= MAX_SEED)
  ) {
    throw new Error(`options.seed must be an integer from 0 to 2^32 - 1 (${MAX_SEED}), got ${show(o.seed)}`);
  }
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
 * candidates, each tagged with its round. The work does not depend on the number of parts: a part stops after
 * round r* + 2 of the global sequence, r* being the first of its rounds with an exact fit, and the merge keeps
 * rounds up to the first exact round of all parts + 2, which every part has run; so any pool merges to one run's
 * answers. Deterministic for (task, seed, rounds) when it ends by its own rule; a budget or an abort returns a
 * prefix of the same work (the first round's screened starts at least, unpolished if need be). Yields to the event
 * loop every YIELD_MS of work, between screening and each local solve; the local solves see the deadline and the
 * signal at every iteration. Throws for a bad task or options.
 */
export async function pathSynthesisPart(
  task: PathTask,
  options: PathSynthesisPartOptions = {},
): Promise<PathSynthesisPartResult> {
  const t = normaliseTask(task);
  checkOptions(options);
  const seed = options.seed ?? 1;
  const budgetMs = options.budgetMs ?? DEFAULT_BUDGET_MS;
  const maxRounds = options.rounds ?? DEFAULT_ROUNDS;
  const parts = options.parts ?? 1;
  const part = options.part ?? 0;
  const signal = options.signal;
  const start = Date.now();
  const deadline = start + budgetMs;
  const scale2 = t.scale * t.scale;
  let candidates: PathCandidate[] = [];
  let evaluations = 0;
  let rounds = 0;
  let best = Infinity;
  let fraction = 0;
  let exactRound = Infinity;
  let lastYield = start;
  let complete = true;
  const myRounds = Math.ceil((maxRounds - part) / parts);
  for (let round = part; round < maxRounds; round += parts) {
    if (round > exactRound + MIN_ROUNDS_AFTER_EXACT) break;
    // The first round runs whatever the budget, so a tiny budget still returns the starts it screened.
    if (signal?.aborted || (rounds > 0 && Date.now() >= deadline)) {
      complete = false;
      break;
    }
    const steps = pathRoundSteps(t, seed, round, deadline, signal);
    let next = steps.next();
    while (!next.done) {
      if (Date.now() - lastYield >= YIELD_MS) {
        await yieldToEventLoop();
        lastYield = Date.now();
      }
      next = steps.next();
    }
    const { candidates: found, stats } = next.value;
    rounds++;
    evaluations += stats.evaluations;
    candidates = candidates.concat(found).sort(byQuality);
    if (candidates.length > PART_KEEP) candidates.length = PART_KEEP;
    if (found.some((c) => c.f <= EXACT_F)) exactRound = Math.min(exactRound, round);
    if (candidates.length > 0) best = Math.min(best, candidates[0].f * scale2);
    fraction = Math.max(
      fraction,
      Math.min(1, rounds / myRounds, 1),
      Math.min(1, (Date.now() - start) / Math.max(1, budgetMs)),
    );
    options.onProgress?.({
      fraction: Math.min(1, fraction),
      best,
      candidates: candidates.slice(0, PROGRESS_CANDIDATES),
    });
  }
  if (signal?.aborted || Date.now() > deadline) complete = false;
  return { candidates, rounds, evaluations, complete };
}

/** Best first; ties by round, branch, direction and then the variables, so the order never depends on the parts. */
function byQuality(a: PathCandidate, b: PathCandidate): number {
  if (a.f !== b.f) return a.f - b.f;
  if (a.round !== b.round) return a.round - b.round;
  if (a.sigma !== b.sigma) return a.sigma - b.sigma;
  if (a.dir !== b.dir) return a.dir - b.dir;
  for (let i = 0; i < a.x.length; i++) if (a.x[i] !== b.x[i]) return a.x[i] - b.x[i];
  return 0;
}

/** Throws unless parts is an array of arrays of candidates of this task's layout, naming the first bad one. */
function checkCandidates(parts: unknown, m: number): asserts parts is PathCandidate[][] {
  if (!Array.isArray(parts)) throw new Error(`parts must be an array of candidate lists, got ${show(parts)}`);
  parts.forEach((list: unknown, i) => {
    if (!Array.isArray(list)) throw new Error(`parts[${i}] must be an array of candidates, got ${show(list)}`);
    list.forEach((c: unknown, j) => {
      const name = `parts[${i}][${j}]`;
      if (typeof c !== 'object' || c === null) throw new Error(`${name} must be a candidate, got ${show(c)}`);
      const r = c as Record<string, unknown>;
      if (r.sigma !== 1 && r.sigma !== -1) throw new Error(`${name}.sigma must be 1 or -1, got ${show(r.sigma)}`);
      if (r.dir !== 1 && r.dir !== -1) throw new Error(`${name}.dir must be 1 or -1, got ${show(r.dir)}`);
      if (!Array.isArray(r.x) || r.x.length !== m || !r.x.every((v) => typeof v === 'number' && Number.isFinite(v))) {
        throw new Error(`${name}.x must be ${m} finite numbers (this task's variables), got ${show(r.x)}`);
      }
      if (typeof r.f !== 'number' || !(r.f >= 0)) throw new Error(`${name}.f must be a number >= 0, got ${show(r.f)}`);
      if (!Number.isInteger(r.round) || (r.round as number) < 0) {
        throw new Error(`${name}.round must be an integer >= 0, got ${show(r.round)}`);
      }
    });
  });
}

/**
 * Merges the candidates of one or more parts into checked, distinct answers, best first (at most 10): the rounds up
 * to the first exact fit's round + 2 are kept (all rounds when none is exact), their best 64 polished and checked.
 * The polish stops at deadline (Date.now(), ms; default none, which makes the merge deterministic) or when signal
 * is aborted. Throws naming a malformed part or candidate.
 */
export function mergePathCandidates(
  task: PathTask,
  parts: PathCandidate[][],
  deadline = Infinity,
  signal?: AbortSignalLike,
): PathSolution[] {
  const t = normaliseTask(task);
  checkCandidates(parts, pathLayout(t).m);
  const all = parts.flat();
  let cut = Infinity;
  for (const c of all) if (c.f <= EXACT_F) cut = Math.min(cut, c.round + MIN_ROUNDS_AFTER_EXACT);
  // Clearing: a candidate that is, unpolished, the same design as a better one kept (sameDesign's rule) gives way,
  // so that copies of one basin do not fill the places of distinct designs (issue 34 item 2).
  const kept: PathCandidate[] = [];
  const keys: DesignKey[] = [];
  for (const c of all.filter((c) => c.round <= cut).sort(byQuality)) {
    if (kept.length >= KEEP) break;
    const key = designKey(t, c);
    if (keys.some((k) => sameKey(k, key))) continue;
    kept.push(c);
    keys.push(key);
  }
  return screenCandidates(t, task, [kept], deadline, signal);
}

/**
 * Path generation: up to 10 distinct four-bars whose coupler point passes nearest the targets (Σd², recomputed
 * from each design), best first; [] when nothing feasible was found. Options: seed (default 1), budgetMs
 * (default 3000), signal, onProgress, rounds (default: no cap, the budget decides). Throws an Error naming the value for a bad task or options.
 */
export async function pathSynthesis(task: PathTask, options: PathSynthesisOptions = {}): Promise<PathSolution[]> {
  if (typeof options !== 'object' || options === null) {
    throw new Error(`options must be an object, got ${show(options)}`);
  }
  // Checked as given, before the budget is split (a bad value is named as the caller wrote it).
  checkOptions(options);
  const start = Date.now();
  const budgetMs = options.budgetMs ?? DEFAULT_BUDGET_MS;
  // The global stage stops at (1 − POLISH_SHARE) of the budget, so the final polish has the rest: a best fit along a
  // flat valley is often reached there (the rounds' solves stop at LOCAL_ITERATIONS).
  const partOptions = { ...options, part: 0, parts: 1, budgetMs: (1 - POLISH_SHARE) * budgetMs };
  const run = await pathSynthesisPart(task, partOptions);
  // The merge's polish gets a tenth of the budget (at most MERGE_MS) past it, or MERGE_MS after an abort; with
  // rounds given and the run ended by its own rule, it is unbounded so that the answers are reproducible.
  const deadline = options.signal?.aborted
    ? Date.now() + MERGE_MS
    : options.rounds !== undefined && run.complete
      ? Infinity
      : Math.max(Date.now(), start + budgetMs) + Math.min(MERGE_MS, 0.1 * budgetMs);
  const solutions = mergePathCandidates(task, [run.candidates], deadline, options.signal);
  options.onProgress?.({ fraction: 1, best: Math.min(solutions[0]?.error ?? Infinity, bestOf(run, task)) });
  return solutions;
}

function bestOf(run: PathSynthesisPartResult, task: PathTask): number {
  const s = normaliseTask(task).scale;
  return run.candidates.length > 0 ? run.candidates[0].f * s * s : Infinity;
}
