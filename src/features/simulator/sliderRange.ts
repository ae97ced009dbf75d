/** A slider's range and step in the field's unit. */
export interface SliderRange {
  min: number;
  max: number;
  step: number;
}

/** The smallest 1, 2 or 5 times a power of ten that is >= x (x > 0). */
export function niceCeil(x: number): number {
  if (!(x > 0) || !Number.isFinite(x)) return 1;
  const p = 10 ** Math.floor(Math.log10(x));
  const m = x / p;
  const k = m <= 1 + 1e-12 ? 1 : m <= 2 + 1e-12 ? 2 : m <= 5 + 1e-12 ? 5 : 10;
  return k * p;
}

/** Slider range for lengths around a longest link of maxLength: 0 to a round number near three times it, 2000 steps. */
export function lengthSliderRange(maxLength: number): SliderRange {
  const max = niceCeil(3 * maxLength);
  const step = max / 2000;
  return { min: step, max, step };
}

/**
 * Whether the length sliders need a new range: some value left it, or the longest link shrank below a
 * fiftieth of it (the sliders would be unusable). Dragging within the range never triggers a change.
 */
export function needsNewRange(range: SliderRange, values: readonly number[]): boolean {
  const maxV = Math.max(...values);
  return values.some((v) => v < range.min || v > range.max) || maxV < range.max / 50;
}
