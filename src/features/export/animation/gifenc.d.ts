// Types for the parts of gifenc 1.0.3 (MIT, no bundled types) that the GIF export uses; see its README.
declare module 'gifenc' {
  /** An RGB colour as [r, g, b], each 0..255. */
  export type GifencColor = number[];
  /** Options of GIFEncoder.writeFrame (delay in milliseconds, rounded by gifenc to centiseconds). */
  export interface GifencFrameOptions {
    palette?: GifencColor[];
    delay?: number;
    /** -1 plays once, 0 loops forever, n > 0 repeats n more times (first frame only). */
    repeat?: number;
    transparent?: boolean;
    transparentIndex?: number;
    dispose?: number;
    first?: boolean;
    colorDepth?: number;
  }
  /** A GIF byte stream being written. */
  export interface GifencEncoder {
    writeFrame(index: Uint8Array, width: number, height: number, opts?: GifencFrameOptions): void;
    finish(): void;
    bytes(): Uint8Array;
    bytesView(): Uint8Array;
    reset(): void;
  }
  /** Creates a GIF stream (auto mode writes the header with the first frame). */
  export function GIFEncoder(opts?: { initialCapacity?: number; auto?: boolean }): GifencEncoder;
  /** A palette of at most maxColors colours for RGBA pixels. */
  export function quantize(
    rgba: Uint8Array | Uint8ClampedArray,
    maxColors: number,
    options?: { format?: 'rgb565' | 'rgb444' | 'rgba4444' },
  ): GifencColor[];
  /** The palette index of each RGBA pixel (nearest colour). */
  export function applyPalette(
    rgba: Uint8Array | Uint8ClampedArray,
    palette: GifencColor[],
    format?: 'rgb565' | 'rgb444' | 'rgba4444',
  ): Uint8Array;
}
