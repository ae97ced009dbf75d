/** Global the UI benchmark sets (through an init script) before the app loads, to ask for timing marks. */
export const BENCH_FLAG = '__FOURBAR_BENCH__';

/** True when the page was opened by the UI benchmark (window.__FOURBAR_BENCH__ set before the app loaded). */
export function benchEnabled(): boolean {
  return typeof window !== 'undefined' && Boolean((window as unknown as Record<string, unknown>)[BENCH_FLAG]);
}

const enabled = benchEnabled();

/**
 * performance.mark(name, { detail }) for npm run bench:ui, and nothing otherwise: an app left open for hours
 * does not grow its performance timeline.
 */
export function benchMark(name: string, detail?: Record<string, unknown>): void {
  if (enabled && typeof performance !== 'undefined' && typeof performance.mark === 'function')
    performance.mark(name, { detail });
}
