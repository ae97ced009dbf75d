export {
  NINE_POINT_PATHS,
  RECHECK_TOL,
  mergeNinePoint,
  ninePointJumps,
  ninePointRefusal,
  ninePointSynthesis,
} from './ninePointSynthesis';
export type {
  NinePointClass,
  NinePointEnd,
  NinePointLinkage,
  NinePointOptions,
  NinePointRefusal,
  NinePointResult,
} from './ninePointSynthesis';
