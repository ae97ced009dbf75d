import type { LinkageScene } from './scene';
import type { AppState } from '../state/appState';
import type { PointResponse } from '../solution';
import type { FrameMotion } from './frameMotion';

/** The frame the linkage view drew last: its state (Play's frame applied), its pose as a point and its scene. */
export interface ShownFrame {
  state: AppState;
  /** The pose on screen as a point (the plots' marker). */
  marker: PointResponse;
  /** Its velocities and accelerations (the rate plots' marker); null where it does not assemble. */
  motion: FrameMotion | null;
  scene: LinkageScene;
}
