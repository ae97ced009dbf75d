/**
 * Four-bar synthesis: function, motion and path generation, built on src/solver. Pure TypeScript: no DOM, React,
 * d3 or worker globals. Radians throughout; lengths in any one unit. See docs/synthesis.md.
 */
export type { PathSolution, PathTask, PlacedFourBar, PlacedJoints, Pose } from './types';
export { checkPlaced, fourBarFromJoints, placedCouplerPoint, placedJoints } from './placed';
export {
  DEFAULT_BUDGET_MS,
  DEFAULT_ROUNDS,
  POLISH_SHARE,
  PROGRESS_CANDIDATES,
  mergePathCandidates,
  pathSynthesis,
  pathSynthesisPart,
} from './pathSynthesis';
export type {
  AbortSignalLike,
  PathProgress,
  PathSynthesisOptions,
  PathSynthesisPartOptions,
  PathSynthesisPartResult,
} from './pathSynthesis';
export type { PathCandidate } from './globalSearch';
export { MODEL_SIZE, couplerLocal } from './pathModel';
export {
  MAX_PAIRS,
  MAX_PRECISION_POINTS,
  NoLinkageError,
  chebyshevPoints,
  freudenstein,
  functionGenerator,
} from './functionGeneration';
export type {
  AnglePair,
  FreudensteinDesign,
  FunctionDefect,
  FunctionGeneratorResult,
  FunctionTask,
  NoLinkageReason,
} from './functionGeneration';
export { motionDesign, threePositionConstruction, threePositionSynthesis } from './motionGeneration';
export type { MotionDesign, PivotConstruction, PivotName, ThreePositionGiven } from './motionGeneration';
export {
  MAX_APPROX_DYADS,
  MAX_APPROX_POSES,
  MIN_APPROX_POSES,
  approximateDyads,
  approximateMotion,
  poseErrors,
} from './motionLeastSquares';
export type { ApproxDyad, ApproxFourBar, ApproxMotion, PoseError } from './motionLeastSquares';
export { screenPoses } from './defects';
export type { MotionDefect, PinPair } from './defects';
export { twoPositionRocker } from './twoPosition';
export type { TwoPositionRocker, TwoPositionRockerTask } from './twoPosition';
export { CURVE_FAR, DEFAULT_CURVE_SAMPLES, burmesterCurves, burmesterFourBars, burmesterPoints } from './burmester';
export type { BurmesterFourBar, BurmesterPair } from './burmester';
export { toFrame, toPlane } from './poseFrame';
export { robertsCognates } from './cognates';
export { SAME_DESIGN, sameDesign } from './pathScreen';
export type { RobertsCognate } from './cognates';
export { NINE_POINT_PATHS, mergeNinePoint, ninePointJumps, ninePointRefusal, ninePointSynthesis } from './ninePoint';
export type {
  NinePointClass,
  NinePointEnd,
  NinePointLinkage,
  NinePointOptions,
  NinePointRefusal,
  NinePointResult,
} from './ninePoint';
// Limits of the synthesis contracts (issue 31; docs/synthesis.md "Limits and refusals").
export { MAX_SEED } from './pathSynthesis';
export { MAX_PATH_TARGETS, MAX_TARGET_SIZE, MIN_TARGET_SIZE } from './pathTask';
