import { deflateSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
import { PNG_SIGNATURE, crc32, isPng, pngDpi, pngSize, withPngDpi } from '../../../src/shared/canvas/png';

function chunk(type: string, data: Uint8Array): Uint8Array {
  const out = new Uint8Array(12 + data.length);
  const dv = new DataView(out.buffer);
  dv.setUint32(0, data.length);
  for (let i = 0; i < 4; i++) out[4 + i] = type.charCodeAt(i);
  out.set(data, 8);
  dv.setUint32(8 + data.length, crc32(out.subarray(4, 8 + data.length)));
  return out;
}

/** A tiny valid 3x2 grey PNG built by hand (independent of the code under test except crc32, checked below). */
function tinyPng(): Uint8Array {
  const ihdr = new Uint8Array(13);
  const dv = new DataView(ihdr.buffer);
  dv.setUint32(0, 3);
  dv.setUint32(4, 2);
  ihdr.set([8, 0, 0, 0, 0], 8);
  const raw = new Uint8Array([0, 1, 2, 3, 0, 4, 5, 6]);
  const parts = [PNG_SIGNATURE, chunk('IHDR', ihdr), chunk('IDAT', deflateSync(raw)), chunk('IEND', new Uint8Array(0))];
  const out = new Uint8Array(parts.reduce((s, p) => s + p.length, 0));
  let o = 0;
  for (const p of parts) {
    out.set(p, o);
    o += p.length;
  }
  return out;
}

describe('crc32', () => {
  it('matches the standard check value', () => {
    expect(crc32(new TextEncoder().encode('123456789'))).toBe(0xcbf43926);
    expect(crc32(new TextEncoder().encode('IEND'))).toBe(0xae426082);
  });
});

describe('withPngDpi', () => {
  it('adds a pHYs chunk after IHDR and keeps the image', () => {
    const png = tinyPng();
    expect(pngDpi(png)).toBeNull();
    const out = withPngDpi(png, 300);
    expect(isPng(out)).toBe(true);
    expect(pngSize(out)).toEqual({ width: 3, height: 2 });
    expect(pngDpi(out)).toBeCloseTo(300, 0);
    expect(out.length).toBe(png.length + 21);
  });
  it('replaces an existing pHYs instead of adding a second', () => {
    const twice = withPngDpi(withPngDpi(tinyPng(), 96), 300);
    expect(pngDpi(twice)).toBeCloseTo(300, 0);
    expect(twice.length).toBe(tinyPng().length + 21);
  });
  it('refuses bytes that are not a PNG', () => {
    expect(() => pngSize(new Uint8Array([1, 2, 3]))).toThrow(/not a PNG/);
  });
});
