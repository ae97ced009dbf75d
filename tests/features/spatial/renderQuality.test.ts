import { describe, expect, it } from 'vitest';
import {
  ADAPT_WINDOW,
  FULL_QUALITY,
  LEAN_QUALITY,
  SLOW_FRAME_MS,
  adaptQuality,
  isSoftwareRenderer,
  pixelRatioFor,
  qualityForRenderer,
} from '../../../src/features/spatial/renderQuality';

// Renderer strings as browsers report them (UNMASKED_RENDERER_WEBGL), hardware and software.
const SOFTWARE = [
  'ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)',
  'Google SwiftShader',
  'llvmpipe (LLVM 15.0.7, 256 bits)',
  'Mesa/X.org, llvmpipe (LLVM 12.0.0, 256 bits)',
  'ANGLE (Microsoft, Microsoft Basic Render Driver Direct3D11 vs_5_0 ps_5_0, D3D11)',
  'softpipe',
  'lavapipe',
];
const HARDWARE = [
  'ANGLE (Intel, Intel(R) UHD Graphics 620 Direct3D11 vs_5_0 ps_5_0, D3D11)',
  'ANGLE (NVIDIA, NVIDIA GeForce RTX 3060 (0x00002503) Direct3D11 vs_5_0 ps_5_0, D3D11)',
  'Apple M1',
  'Mali-G78',
  'Adreno (TM) 650',
  'Mesa Intel(R) Xe Graphics (TGL GT2)',
  'AMD Radeon Pro 5500M OpenGL Engine',
];

describe('isSoftwareRenderer', () => {
  it.each(SOFTWARE)('names %s software', (r) => expect(isSoftwareRenderer(r)).toBe(true));
  it.each(HARDWARE)('names %s hardware', (r) => expect(isSoftwareRenderer(r)).toBe(false));
});

describe('qualityForRenderer', () => {
  it('draws the lean look on a software renderer: no MSAA, pixel ratio 1, fewer segments, one side, thin fixed lines', () => {
    const q = qualityForRenderer(SOFTWARE[0]);
    expect(q).toEqual({
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
    });
  });
  it('keeps the full look on a hardware GPU and when the name is hidden', () => {
    for (const r of [...HARDWARE, null]) expect(qualityForRenderer(r)).toBe(FULL_QUALITY);
    expect(FULL_QUALITY).toMatchObject({
      antialias: true,
      maxPixelRatio: 2,
      movingPixelRatio: 2,
      sphereSegments: [64, 40],
      sphereTwoSided: true,
      sphereShading: 'phong',
      fatFixedLines: true,
      fatMovingLines: true,
      // A GPU draws the full look whole while moving: the fixed parts' layer is for the software WebGL's lean look.
      cacheFixedWhileMoving: false,
    });
  });
});

describe('adaptQuality', () => {
  const frames = (ms: number, n = ADAPT_WINDOW) => Array.from({ length: n }, () => ms);

  it('keeps the full look while frames come at the display rate (60 Hz)', () => {
    expect(adaptQuality(FULL_QUALITY, frames(1000 / 60))).toBe(FULL_QUALITY);
    // 30 frames/s is the edge: 33 ms is not over SLOW_FRAME_MS.
    expect(adaptQuality(FULL_QUALITY, frames(SLOW_FRAME_MS))).toBe(FULL_QUALITY);
  });
  it('lowers the look once the median latency is over two 60 Hz frames, keeping the context’s MSAA', () => {
    const q = adaptQuality(FULL_QUALITY, frames(250));
    expect(q).toEqual({ ...LEAN_QUALITY, antialias: true });
    expect(adaptQuality(FULL_QUALITY, frames(SLOW_FRAME_MS + 0.5))).toMatchObject({ name: 'lean' });
  });
  it('waits for ADAPT_WINDOW frames (the first compile shaders)', () => {
    expect(adaptQuality(FULL_QUALITY, frames(500, ADAPT_WINDOW - 1))).toBe(FULL_QUALITY);
  });
  it('judges the median of the last ADAPT_WINDOW, not a few slow frames or old ones', () => {
    // Five shader-compile stalls among twelve fast frames: the median is fast.
    expect(adaptQuality(FULL_QUALITY, [...frames(400, 5), ...frames(16, 7)])).toBe(FULL_QUALITY);
    // Seven slow of twelve: the median (mean of the 6th and 7th sorted) is slow.
    expect(adaptQuality(FULL_QUALITY, [...frames(16, 5), ...frames(60, 7)]).name).toBe('lean');
    // Slow long ago, fast in the last window: full.
    expect(adaptQuality(FULL_QUALITY, [...frames(300, 20), ...frames(16)])).toBe(FULL_QUALITY);
  });
  it('never raises a lean look back, and hands the same look back while slow (the scene rebuilds on a new one)', () => {
    expect(adaptQuality(LEAN_QUALITY, frames(5))).toBe(LEAN_QUALITY);
    expect(adaptQuality(LEAN_QUALITY, frames(250))).toBe(LEAN_QUALITY);
    const adapted = adaptQuality(FULL_QUALITY, frames(250));
    expect(adaptQuality(adapted, frames(250))).toBe(adapted);
  });
  it('throws on a latency that is not a finite number >= 0, naming the value', () => {
    expect(() => adaptQuality(FULL_QUALITY, [...frames(16), Number.NaN])).toThrow(/latenciesMs.*NaN/);
    expect(() => adaptQuality(FULL_QUALITY, [-1])).toThrow(/latenciesMs.*-1/);
  });
});

describe('pixelRatioFor', () => {
  it('draws the lean look at half its resolution while the view moves, and at full resolution at rest', () => {
    expect(pixelRatioFor(LEAN_QUALITY, 1, true)).toBe(0.5);
    expect(pixelRatioFor(LEAN_QUALITY, 1, false)).toBe(1);
    // A phone's dpr 3 under a software WebGL: the lean look's cap of 1 first.
    expect(pixelRatioFor(LEAN_QUALITY, 3, true)).toBe(0.5);
    expect(pixelRatioFor(LEAN_QUALITY, 3, false)).toBe(1);
  });

  it('never changes the full look’s resolution (a real GPU draws as before, moving or not)', () => {
    for (const dpr of [1, 1.5, 2, 3])
      for (const moving of [true, false]) expect(pixelRatioFor(FULL_QUALITY, dpr, moving)).toBe(Math.min(2, dpr));
  });

  it('throws on a device pixel ratio that is not a positive finite number, naming it', () => {
    expect(() => pixelRatioFor(LEAN_QUALITY, 0, true)).toThrow(
      'devicePixelRatio must be a positive finite number, got 0',
    );
    expect(() => pixelRatioFor(LEAN_QUALITY, Number.NaN, false)).toThrow('devicePixelRatio');
  });
});
