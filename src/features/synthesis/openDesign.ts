import { radToDeg, wrapDeg180, wrapDeg360 } from '../../solver/angles';
import type { Point } from '../../solver/kinematics';
import type { PlacedFourBar } from '../../synthesis/types';
import type { Dispatch } from 'react';
import type { Action, AppState } from '../../shared/state/appState';

/**
 * What a synthesis mode hands to "Open in simulator": the placed design (lengths in the task's unit, angles in
 * radians, O2 and the ground angle in the task's plane), the points to mark on the simulator's canvas (targets,
 * pose points or precision points, in the task's plane) and, optionally, the input angle to open at (θ2 in radians
 * from the design's ground line; default the first marker's, else 0).
 */
export interface OpenDesign {
  design: PlacedFourBar;
  markers: Point[];
  theta2?: number;
}

/** Props every synthesis mode component gets (PathMode, MotionMode, FunctionMode). */
export interface SynthesisModeProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  onOpen(design: OpenDesign): void;
}

/**
 * The app state that shows an opened design in the simulator: its lengths, branch and coupler point (degrees), its
 * placement (O2 and the ground angle, URL ox, oy, og), the markers as the targets (URL tg), θ2 (degrees in
 * [0, 360), 9 decimals like the URL) and the simulator page with Play stopped and a fitted view. The rest is kept.
 */
export function openDesignState(state: AppState, open: OpenDesign): AppState {
  const d = open.design;
  const round9 = (x: number) => Number(x.toFixed(9));
  return {
    ...state,
    design: {
      ...state.design,
      linkage: { ...d.links },
      branch: d.branch,
      coupler: { distance: d.pDist, angleDeg: round9(wrapDeg180(radToDeg(d.pAngle))) },
      placement: { x: d.O2.x, y: d.O2.y, angleDeg: round9(wrapDeg180(radToDeg(d.groundAngle))) },
    },
    motion: { ...state.motion, theta2Deg: round9(wrapDeg360(radToDeg(open.theta2 ?? 0))) % 360, playing: false },
    display: { ...state.display, view: { zoom: 1, panX: 0, panY: 0 } },
    synPath: { ...state.synPath, targets: open.markers.map((p) => ({ x: p.x, y: p.y })) },
    shell: { ...state.shell, page: 'simulator' },
  };
}
