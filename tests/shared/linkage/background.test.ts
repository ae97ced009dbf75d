import { describe, expect, it } from 'vitest';
import { drawLinkageBackground, drawLinkageForeground, sameBackground } from '../../../src/shared/linkage/drawLinkage';
import type { DrawContext } from '../../../src/shared/canvas/drawContext';
import type { LinkageScene } from '../../../src/shared/linkage/scene';
import { fitView } from '../../../src/shared/canvas/view';
import { LINKAGES, sweepScenes } from './fixtures';

/** Every call and style assignment a drawing makes, in order (a Proxy stands in for the 2D context). */
function drawingLog(draw: (ctx: DrawContext) => void): string[] {
  const log: string[] = [];
  const target: Record<string, unknown> = {};
  const ctx = new Proxy(target, {
    get(_t, name: string) {
      if (name === 'measureText') return (text: string) => ({ width: 6 * text.length });
      if (name in target) return target[name];
      return (...args: unknown[]) => log.push(`${name}(${args.map((a) => JSON.stringify(a)).join(',')})`);
    },
    set(_t, name: string, value: unknown) {
      target[name] = value;
      log.push(`${name}=${JSON.stringify(value)}`);
      return true;
    },
  }) as unknown as DrawContext;
  draw(ctx);
  return log;
}

const VIEW = (s: LinkageScene) => fitView(s.bounds, 640, 400, { zoom: 1, panX: 0, panY: 0 });
const background = (s: LinkageScene) => drawingLog((ctx) => drawLinkageBackground(ctx, s, VIEW(s)));

// Both branches' coupler curves (the current one and the other), one set of arrays for every frame of a
// cycle, as the live canvas has them from one cycle answer.
const XS = Float64Array.from([0, 1, 2]);
const YS = Float64Array.from([1, 0, 1]);
function withCurves(s: LinkageScene): LinkageScene {
  return {
    ...s,
    curves: [
      { x: XS, y: YS, current: true },
      { x: YS, y: XS, current: false },
    ],
  };
}

describe('drawLinkageBackground', () => {
  it('draws the same background at every pose of a cycle (Play redraws only the foreground)', () => {
    for (const t of LINKAGES) {
      const scenes = sweepScenes(t, 'open', 'en', 30).map(withCurves);
      const first = background(scenes[0]);
      expect(first.length).toBeGreaterThan(10);
      for (const s of scenes) expect(background(s)).toEqual(first);
    }
  });
});

describe('drawLinkageForeground', () => {
  it('never covers the whole canvas: the cached background stays visible under it', () => {
    for (const s of sweepScenes(LINKAGES[0], 'open', 'en', 45).map(withCurves)) {
      const log = drawingLog((ctx) => drawLinkageForeground(ctx, s, VIEW(s)));
      expect(log.filter((c) => c.startsWith('fillRect(0,0,'))).toEqual([]);
    }
  });
});

describe('sameBackground', () => {
  it('says "same" only when the background drawing is the same, and does for every change of pose alone', () => {
    const [base, other] = sweepScenes(LINKAGES[0], 'open', 'en', 90).map(withCurves);
    const flipped = base.curves.map((c) => ({ ...c, current: !c.current }));
    const variants: [string, LinkageScene][] = [
      ['another pose', other],
      ['angles hidden', { ...base, showAngles: false }],
      ['no ghost pose', { ...base, ghost: null }],
      ['grid off', { ...base, showGrid: false }],
      ['trace off', { ...base, showTrace: false }],
      ['other branch curve hidden', { ...base, showGhost: false }],
      ['current circuit switched', { ...base, curves: flipped }],
      [
        'new curve arrays',
        { ...base, curves: base.curves.map((c) => ({ ...c, x: Float64Array.from(c.x).map((v) => v + 1) })) },
      ],
      ['a longer ground link', { ...base, linkage: { ...base.linkage, r1: base.linkage.r1 + 1 } }],
      ['a longer coupler', { ...base, linkage: { ...base.linkage, r3: base.linkage.r3 + 1 } }],
    ];
    const poseOnly = new Set(['another pose', 'angles hidden', 'no ghost pose', 'a longer coupler']);
    for (const [name, v] of variants) {
      const drawnSame = JSON.stringify(background(base)) === JSON.stringify(background(v));
      // Sound (a kept bitmap is the right one) and, for what Play and drags change, never a needless redraw.
      expect({ name, same: sameBackground(base, v) }).toEqual({ name, same: drawnSame });
      expect({ name, same: drawnSame }).toEqual({ name, same: poseOnly.has(name) });
    }
    // Both answers occur, so the comparison above checks something each way.
    expect(variants.some(([, v]) => sameBackground(base, v))).toBe(true);
    expect(variants.some(([, v]) => !sameBackground(base, v))).toBe(true);
  });
});
