import { describe, expect, it } from 'vitest';
import type { DrawContext } from '../../../src/shared/canvas/drawContext';
import { canvasMeasure } from '../../../src/shared/linkage/drawLinkage';

/** A context whose text is `perChar` pixels a character, counting font sets and measurements. */
function countingContext(perChar: number) {
  const counts = { fontSets: 0, measures: 0 };
  let font = '';
  const ctx = {
    get font() {
      return font;
    },
    set font(f: string) {
      counts.fontSets++;
      font = f;
    },
    measureText(text: string) {
      counts.measures++;
      return { width: perChar * text.length * (font.includes('bold') || font.startsWith('600') ? 2 : 1) };
    },
  } as unknown as DrawContext;
  return { ctx, counts };
}

describe('canvasMeasure', () => {
  it('measures each text once per font and context, and sets the font only when it changes', () => {
    const { ctx, counts } = countingContext(5);
    const m = canvasMeasure(ctx);
    expect(m('O2', 'regular')).toBe(10);
    expect(m('A', 'regular')).toBe(5);
    expect(m('O2', 'regular')).toBe(10);
    expect(counts).toEqual({ fontSets: 1, measures: 2 });
    // A later draw of the same context reuses the widths.
    const again = canvasMeasure(ctx);
    expect(again('O2', 'regular')).toBe(10);
    expect(counts.measures).toBe(2);
    // The bold font is another width.
    expect(m('O2', 'bold')).toBe(m('O2', 'bold'));
    expect(counts.fontSets).toBe(2);
  });

  it('never lends one context’s widths to another', () => {
    const a = canvasMeasure(countingContext(5).ctx);
    const b = canvasMeasure(countingContext(7).ctx);
    expect(a('θ3 44.2°', 'regular')).toBe(40);
    expect(b('θ3 44.2°', 'regular')).toBe(56);
  });
});
