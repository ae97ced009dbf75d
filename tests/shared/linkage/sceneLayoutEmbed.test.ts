import { describe, expect, it } from 'vitest';
import { canvasToolsRect } from '../../../src/shared/canvas/canvasTools';
import type { Px, ScreenRect } from '../../../src/shared/canvas/rect';
import { fitView } from '../../../src/shared/canvas/view';
import type { MeasureText } from '../../../src/shared/linkage/sceneLayout';
import { layoutScene } from '../../../src/shared/linkage/sceneLayout';
import { LINKAGES, measureModel, sweepScenes } from './fixtures';

// Issue 19: in the 760x520 embed (the embed code's own size) "θ3 …" was drawn over the coupler bar and r4 sat
// beside A. Its canvas is 502x253 CSS pixels. The fixture's width model errs wide (0.62 em); headless Chromium's
// sans-serif measures the canvas labels at about 0.54 em, so the layouts are checked at both and in between.

/** The 760x520 embed's canvas, CSS pixels (measured in Chromium). */
const EMBED = { width: 502, height: 253.36 };

/** The fixture's width model scaled to an average glyph width of em (the model's own is 0.62 em). */
const measureAt =
  (em: number): MeasureText =>
  (text, font) =>
    measureModel(text, font) * (em / 0.62);

/** Distance (CSS pixels) from p to the nearest point of box r (0 inside). */
function distanceToBox(p: Px, r: ScreenRect): number {
  const dx = Math.max(r.x - p.x, 0, p.x - (r.x + r.width));
  const dy = Math.max(r.y - p.y, 0, p.y - (r.y + r.height));
  return Math.hypot(dx, dy);
}

/** Distance from segment a-b to box r, by 101 samples along the segment. */
function segmentToBox(a: Px, b: Px, r: ScreenRect): number {
  let best = Infinity;
  for (let i = 0; i <= 100; i++) {
    const t = i / 100;
    best = Math.min(best, distanceToBox({ x: a.x + (b.x - a.x) * t, y: a.y + (b.y - a.y) * t }, r));
  }
  return best;
}

/** Half the drawn width of a link bar (STROKES.link / 2): a box closer than this to the bar's axis covers it. */
const BAR_HALF_WIDTH = 2.5;

describe('layoutScene in the 760x520 embed', () => {
  const report = LINKAGES[0];

  it('keeps every angle label off the link bars, θ2 every 5°, in both languages and at 0.50 to 0.62 em', () => {
    const faults: string[] = [];
    for (const em of [0.5, 0.54, 0.58, 0.62]) {
      for (const lang of ['en', 'zh-TW'] as const) {
        sweepScenes(report, 'open', lang, 5).forEach((scene, k) => {
          const view = fitView(scene.bounds, EMBED.width, EMBED.height, { zoom: 1, panX: 0, panY: 0 });
          const layout = layoutScene(scene, view, measureAt(em), [canvasToolsRect(EMBED.width)]);
          const j = layout.joints;
          if (!j.B) return;
          const bars: Record<string, [Px, Px]> = { r2: [j.O2, j.A], r3: [j.A, j.B], r4: [j.B, j.O4] };
          for (const l of layout.labels) {
            if (!l.id.startsWith('theta') && l.id !== 'mu') continue;
            for (const [bar, [a, b]] of Object.entries(bars))
              if (segmentToBox(a, b, l.box) < BAR_HALF_WIDTH)
                faults.push(`${em} em, ${lang}, θ2 = ${k * 5}°: ${l.id} on ${bar}`);
          }
        });
      }
    }
    expect(faults).toEqual([]);
  });

  it('sets r4 beside its rocker, not beside A, at the embed code’s θ2 = 45°', () => {
    for (const em of [0.5, 0.54, 0.58, 0.62]) {
      const scene = sweepScenes(report, 'open', 'en', 1)[45];
      const view = fitView(scene.bounds, EMBED.width, EMBED.height, { zoom: 1, panX: 0, panY: 0 });
      const layout = layoutScene(scene, view, measureAt(em), [canvasToolsRect(EMBED.width)]);
      const { A, B, O4 } = layout.joints;
      const r4 = layout.labels.find((l) => l.id === 'r4');
      expect(r4, `${em} em`).toBeDefined();
      const toRocker = segmentToBox(B!, O4, r4!.box);
      // Beside its bar: within the first two rings of candidates (2 and 8 px beyond the half width), nearer it than A.
      expect(toRocker, `${em} em`).toBeLessThanOrEqual(BAR_HALF_WIDTH + 8 + 1);
      expect(distanceToBox(A, r4!.box), `${em} em`).toBeGreaterThan(toRocker);
    }
  });
});
