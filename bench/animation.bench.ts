/**
 * Animation export benchmark (Node): GIF size and encode time of one cycle of a linkage-like drawing.
 * Frames come from the planner (planAnimationFrames, the motion of Play) and a small anti-aliased rasterizer
 * (tests/features/export/animation/raster.ts: grid, coupler trace, links, joints), encoded by the export's own GIF writer
 * (src/features/export/animation/gifEncoder.ts: one global palette from sampled frames, unchanged pixels transparent).
 * Cases: 360 frames at 640x360 (the target: under 4 MB) for a crank-rocker and a triple rocker,
 * and 120 frames at 1280x720. Rasterizing is timed apart from encoding. Prints a table and writes
 * bench/results/animation.json. A benchmark, not a test: it reports, it does not fail.
 * Run: npx vite-node bench/animation.bench.ts
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { planAnimationFrames } from '../src/features/export/animation/animationFrames';
import { createGifWriter } from '../src/features/export/animation/gifEncoder';
import { gifFrameDelaysCs } from '../src/features/export/animation/gifTiming';
import { classify } from '../src/solver';
import type { Linkage } from '../src/solver';
import { rangeToDeg } from '../src/shared/state/animation';
import { couplerTrace, drawLinkageFrame } from '../tests/features/export/animation/raster';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..');
const FPS = 30;
const LIMIT_BYTES = 4 * 1024 * 1024;

interface Case {
  name: string;
  linkage: Linkage;
  width: number;
  height: number;
  frames: number;
}

const CASES: Case[] = [
  { name: 'crank-rocker 6-2-5-5', linkage: { r1: 6, r2: 2, r3: 5, r4: 5 }, width: 640, height: 360, frames: 360 },
  { name: 'triple rocker 4-3-3.5-3', linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 }, width: 640, height: 360, frames: 360 },
  { name: 'crank-rocker 6-2-5-5 720p', linkage: { r1: 6, r2: 2, r3: 5, r4: 5 }, width: 1280, height: 720, frames: 120 },
];

function run(c: Case) {
  const range = rangeToDeg(classify(c.linkage).inputRange);
  const plan = planAnimationFrames({ theta2Deg: 45, direction: 1, branch: 'open', range, framesPerCycle: c.frames });
  const trace = couplerTrace(c.linkage, 'open', 360);
  let rasterMs = 0;
  const render = (k: number) => {
    const t = performance.now();
    const f = plan.frames[k];
    const r = drawLinkageFrame(c.width, c.height, c.linkage, f.theta2Rad, f.branch, trace);
    rasterMs += performance.now() - t;
    return r.data;
  };
  const delays = gifFrameDelaysCs(plan.frames.length, FPS);
  const samples = [0, 1, 2, 3, 4, 5].map((i) => render(Math.floor((i * plan.frames.length) / 6)));
  const t0 = performance.now();
  const gif = createGifWriter({ width: c.width, height: c.height, loop: true, paletteSamples: samples });
  const paletteMs = performance.now() - t0;
  let encodeMs = 0;
  for (let k = 0; k < plan.frames.length; k++) {
    const rgba = render(k);
    const t = performance.now();
    gif.addFrame(rgba, delays[k]);
    encodeMs += performance.now() - t;
  }
  const t1 = performance.now();
  const bytes = gif.finish();
  encodeMs += performance.now() - t1;
  return {
    case: c.name,
    kind: plan.kind,
    size: `${c.width}x${c.height}`,
    frames: plan.frames.length,
    colors: gif.colorCount,
    bytes: bytes.length,
    mb: +(bytes.length / (1024 * 1024)).toFixed(2),
    underLimit: bytes.length < LIMIT_BYTES,
    paletteMs: Math.round(paletteMs),
    encodeMs: Math.round(encodeMs),
    encodeMsPerFrame: +(encodeMs / plan.frames.length).toFixed(2),
    rasterMs: Math.round(rasterMs),
  };
}

const results = CASES.map(run);
console.table(results);
mkdirSync(join(ROOT, 'bench', 'results'), { recursive: true });
writeFileSync(
  join(ROOT, 'bench', 'results', 'animation.json'),
  JSON.stringify({ node: process.version, fps: FPS, results }, null, 2),
);
