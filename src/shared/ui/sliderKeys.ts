/** How a slider's keys move an angle: arrows by one step, Page Up/Down by ten, around the circle. */
export interface TurnKeys {
  /** Degrees per arrow press (Page Up/Down move ten of them). */
  step: number;
}

/** Arrow and page keys, as multiples of the step (Right and Up increase, as the native slider does). */
const KEY_STEPS: Readonly<Record<string, number>> = {
  ArrowRight: 1,
  ArrowUp: 1,
  ArrowLeft: -1,
  ArrowDown: -1,
  PageUp: 10,
  PageDown: -10,
};

/** How far a multiple may be off the step grid and still count as on it (float noise of Play and the URL). */
const ON_GRID = 1e-7;

/**
 * The value a key moves an angle slider on [min, max) to, or null for a key it leaves alone: arrows and Page
 * Up/Down go to the next multiple of the step (so 202.98804 goes to 203, not 203.98804) and wrap around (a
 * full turn is 360 / step presses of an arrow, and Left from min goes to the last step below max); Home goes
 * to min and End to the last step below max, never to max, which is min again on the circle.
 */
export function turnKeyValue(key: string, value: number, min: number, max: number, keys: TurnKeys): number | null {
  const span = max - min;
  const last = max - keys.step;
  if (key === 'Home') return min;
  if (key === 'End') return last;
  const n = KEY_STEPS[key];
  if (n === undefined) return null;
  const k = (value - min) / keys.step;
  const base = n > 0 ? Math.floor(k + ON_GRID) : Math.ceil(k - ON_GRID);
  const raw = (base + n) * keys.step;
  return min + (((raw % span) + span) % span);
}
