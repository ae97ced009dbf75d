/** The global a benchmark sets before the app loads (bench/ui.bench.ts, in an init script) to turn marks on. */
export const BENCH_GLOBAL = '__FOURBAR_BENCH__';

/** True when a benchmark asked for performance marks; read once at startup. Off in normal use. */
export const BENCH_MARKS: boolean =
  (globalThis as Record<string, unknown>)[BENCH_GLOBAL] === true && typeof performance?.mark === 'function';

/** performance.mark(name, { detail }) under the benchmark flag, else nothing: the timeline never grows in normal use. */
export function benchMark(name: string, detail?: unknown): void {
  if (BENCH_MARKS) performance.mark(name, { detail });
}
