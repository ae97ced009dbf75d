import { getMessages } from '../../../shared/i18n/i18n';
import { loadLanguage } from '../../../shared/i18n/messageModule';
import type { ForceLayer } from '../../../shared/linkage/forceVectors';
import type { FrameBackground } from '../../../shared/linkage/linkageFrame';
import { drawLinkageFrame } from '../../../shared/linkage/linkageFrame';
import type { Locale } from '../../../shared/state/appState';
import { createStageScene } from '../scene/stageScene';
import type { StagePainter } from './stageLoop';

/**
 * The live stage's painter on an OffscreenCanvas: each frame's scene (createStageScene, the page's scene builder, with
 * forceLayer's pin forces) drawn by drawLinkageFrame over a background bitmap kept while it holds, as the page's
 * canvas draws. A language other than English loads on its first state; its frames wait for it.
 */
export function createStagePainter(forceLayer: ForceLayer | null): StagePainter {
  let canvas: OffscreenCanvas | null = null;
  let size = { width: 0, height: 0, dpr: 1 };
  let background: FrameBackground | null = null;
  /** The languages whose tables have loaded here (English is bundled). */
  const loaded = new Set<Locale>(['en']);
  const buildScene = createStageScene(forceLayer);
  return {
    setCanvas(next) {
      canvas = next;
      background = null;
    },
    setSize(width, height, dpr) {
      size = { width, height, dpr };
    },
    async prepare(state) {
      const locale = state.shell.locale;
      if (loaded.has(locale)) return;
      await loadLanguage(locale);
      loaded.add(locale);
    },
    draw(frame, inputs) {
      const started = performance.now();
      const ctx = canvas?.getContext('2d');
      const { width, height, dpr } = size;
      if (!ctx || width <= 0 || height <= 0) return null;
      const locale = inputs.state.shell.locale;
      if (!loaded.has(locale)) return null;
      const pixelWidth = Math.round(width * dpr);
      const pixelHeight = Math.round(height * dpr);
      if (canvas && (canvas.width !== pixelWidth || canvas.height !== pixelHeight)) {
        canvas.width = pixelWidth;
        canvas.height = pixelHeight;
      }
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      const scene = buildScene(inputs, frame, getMessages(locale));
      const where = { bounds: scene.bounds, view: inputs.state.display.view, width, height };
      const drawn = drawLinkageFrame(ctx, background, scene, where, { dpr, pixelWidth, pixelHeight }, (w, h) => {
        return new OffscreenCanvas(w, h);
      });
      background = drawn.background;
      return performance.now() - started;
    },
  };
}
