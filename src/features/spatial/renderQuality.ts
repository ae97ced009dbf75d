/**
 * How richly the 3D view draws. A real GPU draws the full look; a software WebGL (SwiftShader, llvmpipe: a laptop or
 * school VM without a usable GPU, or headless Chromium with --disable-gpu) runs every fragment on the CPU, where the
 * full look cost about 280 ms of the GPU process's CPU per frame on the spherical view (docs/benchmarks.md, Spatial):
 * there the view draws the lean look. Pure: no three.js, no DOM.
 */
export interface RenderQuality {
  /** 'full' or 'lean' (for tests, bench and the canvas' data-quality attribute). */
  name: 'full' | 'lean';
  /** MSAA on the drawing buffer (a context attribute: fixed once the context is made). */
  antialias: boolean;
  /** The largest device pixel ratio the drawing buffer follows. */
  maxPixelRatio: number;
  /** The largest pixel ratio while the view moves (Play, orbit): fewer pixels to fill; full again at rest. */
  movingPixelRatio: number;
  /** The translucent sphere's width and height segments. */
  sphereSegments: readonly [width: number, height: number];
  /** The sphere's inside drawn too (a second transparent pass over most of the view). */
  sphereTwoSided: boolean;
  /** The sphere's lighting: 'phong' (with a highlight) or 'lambert' (diffuse only, about 15 % cheaper in software). */
  sphereShading: 'phong' | 'lambert';
  /** The fixed lines (great circles, axes, the coupler curve, the pins' paths) as pixel-wide lines; else 1 px lines. */
  fatFixedLines: boolean;
  /**
   * The links and the ground link as three's Line2 (widened in its vertex shader, per segment); else as ribbons built
   * on the page (screenRibbon.ts), plain triangles that a software WebGL draws for far less. Read when the view is made.
   */
  fatMovingLines: boolean;
  /**
   * While only the linkage moves (Play, the camera still), the fixed parts are drawn once into a layer and each frame
   * draws only the moving parts over it (fixedLayer.ts, fixedLayerPlan.ts). For the lean look, whose fixed parts are
   * most of a software WebGL's frame; a GPU draws the full look whole.
   */
  cacheFixedWhileMoving: boolean;
}

/** The full look, for a hardware GPU. */
export const FULL_QUALITY: RenderQuality = {
  name: 'full',
  antialias: true,
  maxPixelRatio: 2,
  movingPixelRatio: 2,
  sphereSegments: [64, 40],
  sphereTwoSided: true,
  sphereShading: 'phong',
  fatFixedLines: true,
  fatMovingLines: true,
  cacheFixedWhileMoving: false,
};

/** The lean look, for a software WebGL or a view whose frames take too long. */
export const LEAN_QUALITY: RenderQuality = {
  name: 'lean',
  antialias: false,
  maxPixelRatio: 1,
  movingPixelRatio: 0.5,
  sphereSegments: [32, 20],
  sphereTwoSided: false,
  sphereShading: 'lambert',
  fatFixedLines: false,
  fatMovingLines: false,
  cacheFixedWhileMoving: true,
};

const SOFTWARE_RENDERERS = /swiftshader|llvmpipe|softpipe|lavapipe|software|basic render driver|mesa offscreen/i;

/** True when a WebGL renderer string (WEBGL_debug_renderer_info's UNMASKED_RENDERER_WEBGL) names a software rasteriser. */
export function isSoftwareRenderer(renderer: string): boolean {
  return SOFTWARE_RENDERERS.test(renderer);
}

/** The look for a renderer string; null (the string is not exposed) gives the full look, which adaptQuality can lower. */
export function qualityForRenderer(renderer: string | null): RenderQuality {
  return renderer !== null && isSoftwareRenderer(renderer) ? LEAN_QUALITY : FULL_QUALITY;
}

/** Drawn frames adaptQuality waits for before judging (the first ones compile shaders). */
export const ADAPT_WINDOW = 12;
/** A median latency (ms) above this over ADAPT_WINDOW frames lowers the look: two 60 Hz frames. */
export const SLOW_FRAME_MS = 33;

/**
 * The look after some drawn frames: the lean look once the median of the last ADAPT_WINDOW latencies (ms, from a
 * change asking for a frame to that frame drawn; one display frame, 16.7 ms at 60 Hz, when the GPU keeps up, since the
 * browser holds the next animation frame back while the GPU is busy) is over SLOW_FRAME_MS; otherwise the current
 * look. Never raises it back (each change of look rebuilds the scene). MSAA is a context attribute, fixed once the
 * context is made, so the result keeps the current antialias. Throws on a latency that is not a finite number ≥ 0.
 */
export function adaptQuality(current: RenderQuality, latenciesMs: readonly number[]): RenderQuality {
  for (const ms of latenciesMs)
    if (!(Number.isFinite(ms) && ms >= 0)) throw new Error(`latenciesMs must be finite and >= 0, got ${ms}`);
  if (current.name === 'lean' || latenciesMs.length < ADAPT_WINDOW) return current;
  const last = latenciesMs.slice(-ADAPT_WINDOW).sort((a, b) => a - b);
  const median = (last[(ADAPT_WINDOW - 1) >> 1] + last[ADAPT_WINDOW >> 1]) / 2;
  return median > SLOW_FRAME_MS ? { ...LEAN_QUALITY, antialias: current.antialias } : current;
}

/** How long (ms) the view waits after its last frame before it draws once more at full resolution (at rest). */
export const REST_MS = 180;

/**
 * The drawing buffer's pixel ratio: the device's (devicePixelRatio), capped by the look's maxPixelRatio, and while the
 * view moves by its movingPixelRatio too. Throws on a devicePixelRatio that is not a positive finite number.
 */
export function pixelRatioFor(q: RenderQuality, devicePixelRatio: number, moving: boolean): number {
  if (!(Number.isFinite(devicePixelRatio) && devicePixelRatio > 0))
    throw new Error(`devicePixelRatio must be a positive finite number, got ${devicePixelRatio}`);
  const ratio = Math.min(q.maxPixelRatio, devicePixelRatio);
  return moving ? Math.min(ratio, q.movingPixelRatio) : ratio;
}
