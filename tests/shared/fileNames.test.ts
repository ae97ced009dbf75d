import { describe, expect, it } from 'vitest';
import { animationFileName, labSvgFileName, svgFileName } from '../../src/shared/fileNames';

const L = { r1: 6, r2: 2, r3: 5, r4: 5 };

describe('animationFileName', () => {
  it('names the cycle, frames, size and format', () => {
    expect(animationFileName(L, 'open', 120, '720p', 'gif')).toBe('fourbar_6-2-5-5_open_cycle_120f_720p.gif');
    expect(animationFileName(L, 'crossed', 36, 'screen', 'webm')).toBe('fourbar_6-2-5-5_crossed_cycle_36f_screen.webm');
  });
});

describe('svgFileName', () => {
  it('is the PNG name without a size, ending in .svg; plots of the cycle carry no angle', () => {
    expect(svgFileName(L, 'open', 45, 'linkage')).toBe('fourbar_6-2-5-5_open_theta2-45_linkage.svg');
    expect(svgFileName(L, 'open', 45, 'both')).toBe('fourbar_6-2-5-5_open_theta3-theta4-vs-theta2.svg');
    expect(labSvgFileName(L, 'open', 1)).toBe('fourbar_6-2-5-5_open_work-precision_step1.svg');
  });
});
