import type { FrameSurface } from '../../../../src/features/export/animation/frameSurface';
import type { FrameContext } from '../../../../src/features/export/animation/types';

interface State {
  a: number;
  d: number;
  e: number;
  f: number;
  clip: [x0: number, y0: number, x1: number, y1: number];
}

function parseHex(css: string): [number, number, number] {
  const m = /^#([0-9a-f]{2})([0-9a-f]{2})([0-9a-f]{2})$/i.exec(css);
  if (!m) throw new Error(`the fake context only fills #rrggbb colours, got ${css}`);
  return [parseInt(m[1], 16), parseInt(m[2], 16), parseInt(m[3], 16)];
}

/**
 * A software stand-in for a canvas in Node: fillRect in #rrggbb with a scale-and-translate transform,
 * save/restore and a rectangular clip, pixels snapped to whole device pixels (no anti-aliasing).
 * Enough for the export's own calls (background, letterbox, clip) and a test's simple drawing.
 */
export function createFakeSurface(width: number, height: number): FrameSurface & { calls: string[] } {
  const data = new Uint8ClampedArray(width * height * 4);
  let s: State = { a: 1, d: 1, e: 0, f: 0, clip: [0, 0, width, height] };
  const stack: State[] = [];
  let path: [number, number, number, number] | null = null;
  const calls: string[] = [];
  const ctx = {
    fillStyle: '#000000',
    setTransform(a: number, _b: number, _c: number, d: number, e: number, f: number) {
      s = { ...s, a, d, e, f };
    },
    save() {
      stack.push({ ...s, clip: [...s.clip] });
    },
    restore() {
      s = stack.pop() ?? s;
    },
    beginPath() {
      path = null;
    },
    rect(x: number, y: number, w: number, h: number) {
      path = [s.a * x + s.e, s.d * y + s.f, s.a * (x + w) + s.e, s.d * (y + h) + s.f];
    },
    clip() {
      if (!path) return;
      s.clip = [
        Math.max(s.clip[0], path[0]),
        Math.max(s.clip[1], path[1]),
        Math.min(s.clip[2], path[2]),
        Math.min(s.clip[3], path[3]),
      ];
    },
    fillRect(x: number, y: number, w: number, h: number) {
      calls.push(`fillRect ${this.fillStyle}`);
      const [r, g, b] = parseHex(this.fillStyle);
      const x0 = Math.round(Math.max(s.clip[0], s.a * x + s.e));
      const y0 = Math.round(Math.max(s.clip[1], s.d * y + s.f));
      const x1 = Math.round(Math.min(s.clip[2], s.a * (x + w) + s.e));
      const y1 = Math.round(Math.min(s.clip[3], s.d * (y + h) + s.f));
      for (let j = Math.max(0, y0); j < Math.min(height, y1); j++) {
        for (let i = Math.max(0, x0); i < Math.min(width, x1); i++) {
          const k = (j * width + i) * 4;
          data[k] = r;
          data[k + 1] = g;
          data[k + 2] = b;
          data[k + 3] = 255;
        }
      }
    },
  };
  return {
    ctx: ctx as unknown as FrameContext,
    width,
    height,
    readPixels: () => data.slice(),
    calls,
  };
}
