import type { CycleParams, SolverMethod, TableParams } from './protocol';

/** Watchdog budgets (ms): a call must be answered within baseMs + perPointMs x its points (a lab: per stage). */
export interface WatchdogOptions {
  /** Extra time for a worker that has not answered yet (loading its script). */
  startMs: number;
  baseMs: number;
  perPointMs: number;
  /** Time allowed between a lab's progress messages. */
  labStageMs: number;
}

/** Default budgets: generous, so a busy laptop never trips them; a dead worker is noticed within seconds. */
export const DEFAULT_WATCHDOG: WatchdogOptions = { startMs: 5000, baseMs: 1500, perPointMs: 0.02, labStageMs: 20_000 };

/** Watchdog budget of a call (ms), from an upper bound of the points it solves (both branches of a cycle). */
export function budgetMs(type: SolverMethod, params: unknown, w: WatchdogOptions): number {
  if (type === 'lab') return w.labStageMs;
  const p = params as Partial<CycleParams & TableParams>;
  const samples = Number(p.samples) || 0;
  const points = type === 'cycle' ? 2 * (samples + 1) : type === 'table' ? samples : 8;
  return w.baseMs + w.perPointMs * points;
}

/** A timer that fires this late (ms) means this thread was busy: the awaited answer may be queued behind it. */
const LATE_MS = 100;

/** Calls onMiss after ms, unless its timer fires late (then it waits ms again); returns the cancel. */
export function armTimer(ms: number, onMiss: () => void): () => void {
  let due = Date.now() + ms;
  let id: ReturnType<typeof setTimeout>;
  const tick = () => {
    if (Date.now() - due <= LATE_MS) return onMiss();
    due = Date.now() + ms;
    id = setTimeout(tick, ms);
  };
  id = setTimeout(tick, ms);
  return () => clearTimeout(id);
}
