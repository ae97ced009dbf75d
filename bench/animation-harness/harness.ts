/**
 * Benchmark harness page (bench/animation.browser.ts builds and serves it; never part of the app): exports
 * one cycle of a linkage drawn by the app's own drawLinkage through exportAnimation, so Chromium runs the
 * real module worker, gifenc chunk and MediaRecorder. Exposes window.__animationHarness.run.
 */
import type { AnimationSize } from '../../src/features/export/animation/exportSize';
import { exportSizePx } from '../../src/features/export/animation/exportSize';
import { planAnimationFrames } from '../../src/features/export/animation/animationFrames';
import type { RenderFrame } from '../../src/features/export/animation/types';
import { drawLinkage } from '../../src/shared/linkage/drawLinkage';
import type { LinkageScene, SceneCurve } from '../../src/shared/linkage/scene';
import { sceneBounds, scenePose } from '../../src/shared/linkage/scene';
import { fitView } from '../../src/shared/canvas/view';
import { classify, solveClosedForm, transmissionAngle } from '../../src/solver';
import type { Linkage } from '../../src/solver';
import { rangeToDeg } from '../../src/shared/state/animation';

/** What one harness run exports. */
export interface HarnessRequest {
  format: 'gif' | 'webm';
  linkage: Linkage;
  theta2Deg: number;
  framesPerCycle: number;
  size: AnimationSize;
  viewWidth: number;
  viewHeight: number;
  fps: number;
  loop: boolean;
  /** Abort after this many frames (progress), to try Cancel. */
  cancelAfter?: number;
}

/** What it reports: the outcome, the file as base64, where the GIF was encoded, the time and main-thread long tasks. */
export interface HarnessResult {
  status: string;
  reason?: string;
  encoder?: string;
  mimeType?: string;
  base64?: string;
  bytes?: number;
  ms: number;
  width: number;
  height: number;
  frames: number;
  longTasksMs: number[];
  progressEvents: number;
}

const COUPLER = { distance: 3, angleRad: 0.6 };

function scene(l: Linkage, theta2: number, branch: 'open' | 'crossed', curves: SceneCurve[]): LinkageScene {
  const a = solveClosedForm(l, theta2, branch);
  const pose = a ? scenePose(l, { theta2, ...a, mu: transmissionAngle(a) }, COUPLER) : null;
  return {
    linkage: l,
    theta2,
    pose,
    ghost: null,
    curves,
    showGrid: true,
    showAngles: true,
    showGhost: false,
    showTrace: true,
    text: {
      O2: 'O2',
      O4: 'O4',
      A: 'A',
      B: 'B',
      P: 'P',
      warning: null,
      warningDetail: null,
      gridSpacing: (s) => `grid ${s}`,
      formatAngle: (d) => `${d.toFixed(1)}°`,
      formatLength: (x) => x.toPrecision(4),
    },
    bounds: sceneBounds(l, [], curves, []),
  };
}

function trace(l: Linkage, branch: 'open' | 'crossed'): SceneCurve {
  const n = 361;
  const x = new Float64Array(n);
  const y = new Float64Array(n);
  for (let k = 0; k < n; k++) {
    const t = (2 * Math.PI * k) / (n - 1);
    const a = solveClosedForm(l, t, branch);
    const p = a ? scenePose(l, { theta2: t, ...a, mu: 0 }, COUPLER) : null;
    x[k] = p ? p.P.x : Number.NaN;
    y[k] = p ? p.P.y : Number.NaN;
  }
  return { x, y, current: true };
}

function toBase64(bytes: Uint8Array): string {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

async function run(req: HarnessRequest): Promise<HarnessResult> {
  const { exportAnimation } = await import('../../src/features/export/animation/animationExport');
  const l = req.linkage;
  const range = rangeToDeg(classify(l).inputRange);
  const plan = planAnimationFrames({
    theta2Deg: req.theta2Deg,
    direction: 1,
    branch: 'open',
    range,
    framesPerCycle: req.framesPerCycle,
  });
  const curves = [trace(l, 'open')];
  const fixedBounds = sceneBounds(l, [], curves, []);
  const renderFrame: RenderFrame = (ctx, f, w, h) => {
    const s = { ...scene(l, f.theta2Rad, f.branch, curves), bounds: fixedBounds };
    drawLinkage(ctx, s, fitView(fixedBounds, w, h, { zoom: 1, panX: 0, panY: 0 }));
  };
  const { width, height } = exportSizePx(req.size, req.viewWidth, req.viewHeight, 1);
  const longTasksMs: number[] = [];
  const obs = new PerformanceObserver((list) => {
    for (const e of list.getEntries()) longTasksMs.push(Math.round(e.duration));
  });
  try {
    obs.observe({ type: 'longtask', buffered: false });
  } catch {
    // No long-task timing in this browser: the list stays empty.
  }
  const ac = new AbortController();
  let progressEvents = 0;
  const t0 = performance.now();
  const r = await exportAnimation({
    format: req.format,
    frames: plan.frames,
    width,
    height,
    viewWidth: req.viewWidth,
    viewHeight: req.viewHeight,
    fps: req.fps,
    loop: req.loop,
    renderFrame,
    signal: ac.signal,
    onProgress: (p) => {
      progressEvents++;
      if (req.cancelAfter !== undefined && p.framesDone >= req.cancelAfter) ac.abort();
    },
  });
  const ms = Math.round(performance.now() - t0);
  obs.disconnect();
  const base = { ms, width, height, frames: plan.frames.length, longTasksMs, progressEvents, status: r.status };
  if (r.status === 'unsupported') return { ...base, reason: r.reason };
  if (r.status !== 'done') return base;
  const bytes = new Uint8Array(await r.blob.arrayBuffer());
  return {
    ...base,
    encoder: (r as { encoder?: string }).encoder ?? 'media-recorder',
    mimeType: r.blob.type,
    bytes: bytes.length,
    base64: toBase64(bytes),
  };
}

(window as unknown as { __animationHarness: { run: typeof run } }).__animationHarness = { run };
document.getElementById('status')!.textContent = 'ready';
