import { describe, expect, it } from 'vitest';
import { MAX_SIDE_PX, exportSizePx, letterbox } from '../../../../src/features/export/animation/exportSize';

describe('exportSizePx', () => {
  it('gives the view times devicePixelRatio for screen, in even pixels', () => {
    expect(exportSizePx('screen', 800, 450, 1)).toEqual({ width: 800, height: 450 });
    expect(exportSizePx('screen', 801, 451, 2)).toEqual({ width: 1602, height: 902 });
    // 641 x 361 at ratio 1 rounds to the nearest even sides.
    expect(exportSizePx('screen', 641.4, 360.6, 1)).toEqual({ width: 642, height: 360 });
  });

  it('gives 1280 x 720 for 720p whatever the view', () => {
    expect(exportSizePx('720p', 500, 500, 3)).toEqual({ width: 1280, height: 720 });
  });

  it('caps a huge screen at 4096 pixels keeping the aspect ratio', () => {
    const s = exportSizePx('screen', 3000, 1500, 2);
    expect(s.width).toBe(MAX_SIDE_PX);
    expect(s.height).toBe(2048);
  });

  it('names a bad view size', () => {
    expect(() => exportSizePx('screen', 0, 400, 1)).toThrow(/viewWidth.*got 0/);
    expect(() => exportSizePx('screen', 400, 400, Number.NaN)).toThrow(/devicePixelRatio.*got NaN/);
  });
});

describe('letterbox', () => {
  it('fits a square view into 16:9 with bars left and right', () => {
    expect(letterbox(600, 600, 1280, 720)).toEqual({ scale: 1.2, offsetX: 280, offsetY: 0 });
  });

  it('fits a wide view into 16:9 with bars above and below', () => {
    const b = letterbox(1000, 400, 1280, 720);
    expect(b.scale).toBeCloseTo(1.28, 12);
    expect(b.offsetX).toBeCloseTo(0, 12);
    expect(b.offsetY).toBeCloseTo((720 - 512) / 2, 12);
  });

  it('is the plain devicePixelRatio scale for the screen size', () => {
    expect(letterbox(640, 360, 1280, 720)).toEqual({ scale: 2, offsetX: 0, offsetY: 0 });
  });
});
