/** Watchdog budgets of a job client (ms). */
export interface WatchdogOptions {
  /** Extra time for a worker that has not answered yet (loading its script). */
  startMs: number;
  /** Budget of a call whose job declares none. */
  callMs: number;
}

/** Default budgets: generous, so a busy laptop never trips them; a dead worker is noticed within seconds. */
export const DEFAULT_WATCHDOG: WatchdogOptions = { startMs: 5000, callMs: 1500 };

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
