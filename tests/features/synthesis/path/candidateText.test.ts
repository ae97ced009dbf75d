import { describe, expect, it } from 'vitest';
import { distanceText, errorSumText } from '../../../../src/features/synthesis/path/CandidateList';

describe('errorSumText and distanceText', () => {
  it('print an exact fit’s rounding noise as 0 and a real error in full, with the U+2212 minus', () => {
    // Targets' size 2: noise is at most 1e-12 · 2 in a distance, its square in Σd².
    expect(distanceText(5.184e-15, 2)).toBe('0');
    expect(errorSumText(1.242e-28, 2)).toBe('0');
    expect(errorSumText(3.9e-24, 2)).toBe('0');
    // Just above the line, and an ordinary fit: shown.
    expect(errorSumText(4.1e-24, 2)).toBe('4.100e\u221224');
    expect(distanceText(2.1e-12, 2)).toBe('2.100e\u221212');
    expect(errorSumText(1.82e-3, 2)).toBe('1.820e\u22123');
  });
});
