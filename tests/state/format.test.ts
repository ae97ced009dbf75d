import { describe, expect, it } from 'vitest';
import { csvFileName, pngFileName } from '../../src/state/fileNames';
import { fileNumber, formatDeg, formatIntervalsDeg, formatNumber, formatSci } from '../../src/state/format';
import { lengthSliderRange, needsNewRange, niceCeil } from '../../src/state/sliderRange';

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

describe('formatDeg and formatSci', () => {
  it('never shows -0 or NaN', () => {
    expect(formatDeg(-0.001, 2)).toBe('0.00');
    expect(formatDeg(Number.NaN)).toBe('—');
    expect(formatDeg(-12.345, 1)).toBe('\u221212.3');
    expect(formatSci(1.234e-12)).toBe('1.23e\u221212');
    expect(formatSci(0)).toBe('0');
  });
  it('formats the input range', () => {
    expect(formatIntervalsDeg([{ lo: -Math.PI / 2, hi: Math.PI / 2 }], (a, b) => `${a}..${b}`)).toBe(
      '\u221290.00..90.00',
    );
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
