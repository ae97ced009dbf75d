/// <reference lib="webworker" />
import { getMessages } from '../shared/i18n/i18n';
import { loadLanguage } from '../shared/i18n/messageModule';
import type { FrameBackground } from '../shared/linkage/linkageFrame';
import { drawLinkageFrame } from '../shared/linkage/linkageFrame';
import type { InputRangeDeg } from '../shared/state/animation';
import { advanceTheta2, degreesForElapsed } from '../shared/state/animation';
import type { Locale } from '../shared/state/appState';
import type { PlayFrame } from '../shared/state/playhead';
import type { CycleResponse } from '../shared/solution';
import { createForceLayer } from '../features/forces/forceLayer';
import type { StageInputs } from '../features/simulator/scene/stageScene';
import { createStageScene } from '../features/simulator/scene/stageScene';
import type { StageReply, StageRequest } from './stageProtocol';

declare const self: DedicatedWorkerGlobalScope;

/** Longest frame step, seconds, as useAnimationFrame caps it on the page: a backgrounded tab does not jump on return. */
const MAX_DT_SECONDS = 0.1;

/** What Play is doing: the frame drawn last, when, and how it moves. */
interface Playing {
  id: number;
  frame: PlayFrame;
  atEpochMs: number;
  speedDegPerFrame: number;
  range: InputRangeDeg;
  /** The first step from the page's frame is not capped: the worker catches up with the page's clock. */
  first: boolean;
}

let canvas: OffscreenCanvas | null = null;
let size = { width: 0, height: 0, dpr: 1 };
let inputs: StageInputs | null = null;
let cycle: CycleResponse | null = null;
let playing: Playing | null = null;
let handle = 0;
let background: FrameBackground | null = null;
/** The languages whose tables have loaded here (English is bundled). */
const loaded = new Set<Locale>(['en']);
const buildScene = createStageScene(createForceLayer());
const reply = (message: StageReply) => self.postMessage(message);
const epochNow = (now: number) => performance.timeOrigin + now;

/**
 * Draws frame on the canvas and returns how long the scene and the drawing took (ms); null when there is nothing to
 * draw on or from yet, or its language is loading.
 */
function draw(frame: PlayFrame): number | null {
  const started = performance.now();
  const ctx = canvas?.getContext('2d');
  const { width, height, dpr } = size;
  if (!ctx || !inputs || width <= 0 || height <= 0) return null;
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
}

function tick(now: number) {
  handle = 0;
  const p = playing;
  if (!p) return;
  const at = epochNow(now);
  const elapsed = Math.max(0, (at - p.atEpochMs) / 1000);
  const dt = p.first ? elapsed : Math.min(MAX_DT_SECONDS, elapsed);
  const next = advanceTheta2(
    p.frame.theta2Deg,
    degreesForElapsed(p.speedDegPerFrame, dt),
    p.frame.direction,
    p.frame.branch,
    p.range,
  );
  const drawMs = draw(next);
  if (drawMs !== null) {
    playing = { ...p, frame: next, atEpochMs: at, first: false };
    reply({ type: 'drawn', id: p.id, frame: next, atEpochMs: at, shownEpochMs: at, drawMs });
  }
  handle = requestAnimationFrame(tick);
}

function setLocale(locale: Locale) {
  if (loaded.has(locale)) return;
  void loadLanguage(locale).then(() => loaded.add(locale));
}

self.onmessage = (e: MessageEvent<StageRequest>) => {
  const m = e.data;
  switch (m.type) {
    case 'canvas':
      canvas = m.canvas;
      background = null;
      if (typeof self.requestAnimationFrame !== 'function') reply({ type: 'unsupported' });
      break;
    case 'size':
      size = { width: m.width, height: m.height, dpr: m.dpr };
      break;
    case 'state':
      inputs = { state: m.state, cycle, ghostShown: m.ghostShown };
      setLocale(m.state.shell.locale);
      break;
    case 'cycle':
      cycle = m.cycle;
      if (inputs) inputs = { ...inputs, cycle };
      break;
    case 'play':
      playing = { ...m, first: true };
      if (!handle && typeof self.requestAnimationFrame === 'function') handle = requestAnimationFrame(tick);
      break;
    case 'show':
      // A θ2 drag: drawn at once (its input came with a page frame), nothing moves it on.
      playing = null;
      if (handle) cancelAnimationFrame(handle);
      handle = 0;
      const drawMs = draw(m.frame);
      if (drawMs !== null) {
        // Told once the frame it went out with has begun (as the page's own measure of a rendered frame).
        const at = epochNow(performance.now());
        const { id, frame } = m;
        requestAnimationFrame(() =>
          reply({ type: 'drawn', id, frame, atEpochMs: at, shownEpochMs: epochNow(performance.now()), drawMs }),
        );
      }
      break;
    case 'stop':
      playing = null;
      if (handle) cancelAnimationFrame(handle);
      handle = 0;
      break;
  }
};
