import type { SpatialBranchName } from '../../shared/state/slices/spatialSlice';
import type { SpatialModel } from '../../spatial';
import type { ViewRates } from './keyHold';
import type { RenderQuality } from './renderQuality';
import type { SceneLinkage, ScenePose } from './sceneData';
import type { Projection } from './spatialScene';
import type { SpatialInput } from './useSpatialAnalysis';

/** What Play runs in the 3D view's worker: the linkage's model and input motion, and where it starts. */
export interface PlayRun {
  model: SpatialModel;
  input: SpatialInput;
  theta2Deg: number;
  branch: SpatialBranchName;
}

/** A change of the camera, as SpatialScene's orbitBy, zoomBy, panBy and resetView take it. */
export type ViewMove =
  | { op: 'orbit'; dAzimuth: number; dElevation: number }
  | { op: 'zoom'; factor: number }
  | { op: 'pan'; dx: number; dy: number }
  | { op: 'reset' };

/**
 * The page's requests to the 3D view's worker (spatialScene.worker.ts), keyed on type. The worker draws on the canvas
 * handed over in init, runs Play on its own animation frames while a run is set, moves the camera on them while keys
 * are held (hold: their speeds, null when none is), and holds the page's last pose for when Play stops.
 */
export type ViewRequest =
  | { type: 'init'; canvas: OffscreenCanvas; rendererName: string | null; devicePixelRatio: number }
  | { type: 'resize'; widthPx: number; heightPx: number; devicePixelRatio: number }
  | { type: 'linkage'; linkage: SceneLinkage }
  | { type: 'pose'; pose: ScenePose | null }
  | { type: 'projection'; projection: Projection }
  | { type: 'move'; move: ViewMove }
  | { type: 'play'; run: PlayRun | null }
  | { type: 'hold'; rates: ViewRates | null }
  | { type: 'png'; id: number; scale: number };

/** Where the worker's Play is after a frame: θ2 (degrees), the branch, and whether it turned at a limit on this frame. */
export interface PlayAt {
  theta2Deg: number;
  branch: SpatialBranchName;
  turned: boolean;
}

/**
 * The worker's replies, keyed on type: ready (the view drew its first frame) or failed (WebGL could not start there:
 * the page draws on its own thread instead); each drawn frame with its count (and of those, the frames drawn on the
 * fixed parts' layer) and, during Play, where Play is; a change
 * of look; a PNG asked for by id (its bytes, or the error's message).
 */
export type ViewReply =
  | { type: 'ready' }
  | { type: 'failed'; message: string }
  | { type: 'frame'; frames: number; layerFrames: number; play: PlayAt | null }
  | { type: 'quality'; name: RenderQuality['name']; antialias: boolean }
  | { type: 'png'; id: number; ok: true; bytes: Uint8Array }
  | { type: 'png'; id: number; ok: false; message: string };
