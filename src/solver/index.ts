/**
 * Four-bar position analysis: classification, a stable closed form, Newton-Raphson and
 * continuation sweeps. Pure TypeScript: no DOM, React, d3 or worker globals.
 * Angles are radians, counter-clockwise from the ground line (O2 at the origin, O4 at (r1, 0)),
 * reported wrapped to (-pi, pi]. Lengths are in any one unit.
 */
export type {
  AngleInterval,
  Angles,
  Branch,
  Classification,
  InputRange,
  IterationRecord,
  Linkage,
  LinkageType,
  NewtonOptions,
  NewtonResult,
  NewtonStatus,
  PointStatus,
  SweepMethod,
  SweepOptions,
  SweepResult,
} from './types';
export { PI, TWO_PI, angleDiff, degToRad, radToDeg, wrapAngle } from './angles';
export { classify, inputRange } from './classify';
export { solveClosedForm } from './closedForm';
export { couplerPoint, jointPositions, loopResidual, transmissionAngle, velocityRatios } from './kinematics';
export type { Joints, Point } from './kinematics';
export {
  DEFAULT_TOLERANCE,
  MAX_STEP_RAD,
  SEED_MAX_ITERATIONS,
  SEED_SINGULAR_DET,
  SEED_TOLERANCE,
  solveNewton,
} from './newton';
export { POINT_STATUSES, STATUS_CODE } from './pointStatus';
export { DEFAULT_SWEEP_METHOD, MAX_SWEEP_POINTS, SWEEP_METHODS, seedFirstGuess, sweep, theta2Grid } from './sweep';
export { validateLinkage } from './validate';
export { MAX_GRID_ANGLE_RAD, adaptiveGrid, adaptiveSweep } from './sampling';
export type { AdaptiveGridOptions, AdaptiveSweepOptions, AdaptiveSweepResult } from './sampling';
export { LIMIT_SIN_MU, couplerPointMotion, linkRates, sweepRates } from './rates';
export type { InputMotion, LinkRates, PointMotion, SweepRates } from './rates';
export { designMetrics } from './metrics';
export type { DeadCentre, DesignMetrics, TransmissionExtremes } from './metrics';
export { PARALLEL_SIN, instantCenters } from './instantCenters';
export type { InstantCenters } from './instantCenters';
export { linkForces, sweepForces } from './forces';
export type { JointForces, LinkInertia, LinkInertias, Loads, SweepForces } from './forces';
export { DEFAULT_CYCLE_POINTS, DEFAULT_SPEED_FLUCTUATION, forceCycle, torqueCycleStats } from './forcesCycle';
export type {
  ForceCycle,
  ForceCycleOptions,
  ForceCycleStatus,
  TorqueCycleStats,
  TorqueCycleStatus,
} from './forcesCycle';
