import { describe, expect, it } from 'vitest';
import { csvFileName, pngFileName } from '../../src/shared/fileNames';
import { SPEED_MAX, SPEED_MIN, SPEED_STEP } from '../../src/shared/state/appState';
import {
  THETA2_DECIMALS,
  fieldText,
  fileNumber,
  formatDeg,
  formatNumber,
  formatSci,
  roundingNoiseToZero,
  truncateText,
} from '../../src/shared/format';
import { lengthSliderRange, needsNewRange, niceCeil } from '../../src/features/simulator/sliderRange';
import type { SliderRange } from '../../src/features/simulator/sliderRange';
import { parseField } from '../../src/shared/ui/validateNumber';

describe('formatNumber', () => {
  it('shows six significant digits, exponent form for extreme scales, a dash for non-finite', () => {
    expect(formatNumber(6)).toBe('6');
    expect(formatNumber(2.000000001)).toBe('2');
    expect(formatNumber(2.000000001, 10)).toBe('2.000000001');
    expect(formatNumber(1e-7)).toBe('1e\u22127');
    expect(formatNumber(12345678)).toBe('1.23457e7');
    expect(formatNumber(-0.5)).toBe('\u22120.5');
    expect(formatNumber(Number.NaN)).toBe('—');
  });
});

describe('formatNumber signs and rounding noise', () => {
  it('writes every minus, in the exponent too, as U+2212', () => {
    expect(formatNumber(-1.5e-7)).toBe('\u22121.5e\u22127');
    expect(formatSci(-1.5e-7)).toBe('\u22121.50e\u22127');
    for (const x of [-1.5e-7, 2e-9, -3e12, -0.25]) {
      expect(formatNumber(x)).not.toContain('-');
      expect(formatSci(x)).not.toContain('-');
    }
  });

  it('shows a value 1e-12 or less of the scale beside it as 0, and a larger one as itself', () => {
    expect(roundingNoiseToZero(1e-17, 1)).toBe(0);
    expect(roundingNoiseToZero(-1e-12, 1)).toBe(0);
    expect(roundingNoiseToZero(2e-12, 1)).toBe(2e-12);
    expect(roundingNoiseToZero(1e-17, 1e-17)).toBe(1e-17);
    expect(formatNumber(1e-17, 6, 1)).toBe('0');
    expect(formatNumber(-3e-15, 6, 10)).toBe('0');
    expect(formatNumber(1e-17)).toBe('1e\u221217');
  });
});

describe('formatDeg and formatSci', () => {
  it('never shows -0 or NaN', () => {
    expect(formatDeg(-0.001, 2)).toBe('0.00');
    expect(formatDeg(Number.NaN)).toBe('—');
    expect(formatDeg(-12.345, 1)).toBe('\u221212.3');
    expect(formatSci(1.234e-12)).toBe('1.23e\u221212');
    expect(formatSci(0)).toBe('0');
  });
});

describe('file names', () => {
  it('are ASCII and say what the file holds', () => {
    const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
    expect(pngFileName(l, 'open', 45, 'linkage', '2x')).toBe('fourbar_6-2-5-5_open_theta2-45_linkage_2x.png');
    expect(pngFileName(l, 'crossed', 45, 'theta3', 'print')).toBe(
      'fourbar_6-2-5-5_crossed_theta3-vs-theta2_300dpi.png',
    );
    expect(pngFileName(l, 'open', 12.3456, 'convergence', 'screen')).toBe(
      'fourbar_6-2-5-5_open_theta2-12.35_nr-convergence_screen.png',
    );
    expect(csvFileName({ r1: 1e-7, r2: 2.5, r3: 5, r4: 5 }, 'open', 360)).toBe(
      'fourbar_1e-7-2.5-5-5_open_cycle_n360.csv',
    );
    expect(fileNumber(-1.5)).toBe('m1.5');
  });
});

describe('slider ranges', () => {
  it('cover three times the longest link with a round maximum', () => {
    expect(niceCeil(18)).toBe(20);
    expect(niceCeil(2)).toBe(2);
    expect(lengthSliderRange(6)).toEqual({ min: 0.01, max: 20, step: 0.01 });
    expect(lengthSliderRange(3e-7).max).toBeCloseTo(1e-6, 20);
  });
  it('re-range only when a value leaves the range or the links shrink far below it', () => {
    const r = lengthSliderRange(6);
    expect(needsNewRange(r, [6, 2, 5, 5])).toBe(false);
    expect(needsNewRange(r, [60, 2, 5, 5])).toBe(true);
    expect(needsNewRange(r, [1e-7, 1e-7, 1e-7, 1e-7])).toBe(true);
  });
});

describe('fieldText', () => {
  it('shows θ2 after Play to the field precision, without float noise', () => {
    expect(fieldText(255.045227, THETA2_DECIMALS)).toBe('255.05');
    expect(fieldText(248.98895999999954, THETA2_DECIMALS)).toBe('248.99');
    expect(fieldText(45, THETA2_DECIMALS)).toBe('45');
    expect(fieldText(120.25, THETA2_DECIMALS)).toBe('120.25');
    expect(fieldText(-0.001, THETA2_DECIMALS)).toBe('0');
  });
  it('shows other fields exactly', () => {
    expect(fieldText(2.000000001)).toBe('2.000000001');
    expect(fieldText(1e-7)).toBe('1e-7');
  });
});

describe('truncateText', () => {
  it('cuts long text to the limit with an ellipsis and leaves short text alone', () => {
    expect(truncateText('abc')).toBe('abc');
    const long = '1'.repeat(400);
    expect(truncateText(long)).toBe('1'.repeat(23) + '…');
    expect(Array.from(truncateText(long, 10))).toHaveLength(10);
    expect(truncateText('x'.repeat(24))).toBe('x'.repeat(24));
  });
  it('never splits a character outside the BMP', () => {
    expect(truncateText('𝜃'.repeat(30), 5)).toBe('𝜃𝜃𝜃𝜃…');
  });
});

/** The browser's rule (oracle for the speed slider):
 * The value a range input shows for value (HTML's step rule): clamped to [min, max], then the nearest
 * min + k * step, the larger one on a tie. A field and its slider agree when this returns the value itself.
 */
function sliderShows(value: number, range: SliderRange): number {
  const v = Math.min(range.max, Math.max(range.min, value));
  const k = Math.floor((v - range.min) / range.step + 0.5);
  return Math.min(range.max, range.min + k * range.step);
}

describe('sliderShows', () => {
  const speed = { min: SPEED_MIN, max: SPEED_MAX, step: SPEED_STEP };
  it('shows every typed speed on the speed slider as stored (0,75 is 0.75, not 1)', () => {
    for (const typed of ['0,75', '0.5', '1.25', '2.5', '9.95', '10', '3.15']) {
      const r = parseField('speed', typed);
      if (!r.ok) throw new Error(`${typed} rejected`);
      // The step grid is k * 0.05 from 0.5; a shown value equal to the stored one to 1e-12 is the same on screen.
      expect(Math.abs(sliderShows(r.value, speed) - r.value), typed).toBeLessThan(1e-12);
    }
  });
  it('follows the HTML step rule: nearest step from min, ties up, clamped', () => {
    expect(sliderShows(0.75, { min: 0.5, max: 10, step: 0.5 })).toBe(1);
    expect(sliderShows(0.7, { min: 0.5, max: 10, step: 0.5 })).toBe(0.5);
    expect(sliderShows(50, { min: 0.5, max: 10, step: 0.5 })).toBe(10);
  });
});
