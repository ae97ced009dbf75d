import type { Point } from '../../solver/kinematics';
import type { PlacedFourBar } from '../../synthesis/types';

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
