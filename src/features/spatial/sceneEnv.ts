import type { RenderQuality } from './renderQuality';

/**
 * What the 3D view needs from where it runs (the page's thread or a worker with an OffscreenCanvas): the WebGL
 * renderer's name (probed on the page, null where not exposed), the device pixel ratio, and where it tells of its frames
 * and of a change of look. No DOM: the same scene code runs in both places.
 */
export interface SceneEnv {
  rendererName: string | null;
  devicePixelRatio: number;
  /** After each drawn frame: frames drawn so far, and of them those drawn on the fixed parts' layer (fixedLayer.ts). */
  onFrame(frames: number, layerFrames: number): void;
  /** When the look is chosen or lowered (renderQuality), with the context's MSAA as made. */
  onQuality(quality: RenderQuality, antialias: boolean): void;
}
