import { describe, expect, it } from 'vitest';
import { GIF_MIN_DELAY_CS, gifFrameDelaysCs } from '../../../../src/features/export/animation/gifTiming';

describe('gifFrameDelaysCs', () => {
  it('keeps the running total on time: 30 FPS alternates 3 and 4 cs and 30 frames last exactly 1 s', () => {
    const d = gifFrameDelaysCs(30, 30);
    expect(d.slice(0, 6)).toEqual([3, 4, 3, 3, 4, 3]);
    expect(d.reduce((s, x) => s + x, 0)).toBe(100);
    expect(gifFrameDelaysCs(120, 20)).toEqual(Array(120).fill(5));
  });

  it('never writes a delay browsers would slow down to 10 cs', () => {
    // Chrome, Firefox and Safari play a delay of 0 or 1 cs as 10 cs: 2 cs (50 FPS) is the fastest honoured.
    expect(GIF_MIN_DELAY_CS).toBe(2);
    expect(Math.min(...gifFrameDelaysCs(60, 60))).toBe(2);
    expect(Math.min(...gifFrameDelaysCs(10, 1000))).toBe(2);
  });

  it('names a bad count or rate', () => {
    expect(() => gifFrameDelaysCs(0, 30)).toThrow(/frameCount.*got 0/);
    expect(() => gifFrameDelaysCs(10, 0)).toThrow(/fps.*got 0/);
    expect(() => gifFrameDelaysCs(10, Number.NaN)).toThrow(/fps.*got NaN/);
  });
});
