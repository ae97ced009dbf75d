export {
  NINE_POINT_PATHS,
  RECHECK_TOL,
  mergeNinePoint,
  ninePointRefusal,
  ninePointSynthesis,
} from './ninePointSynthesis';
export type {
  NinePointClass,
  NinePointLinkage,
  NinePointOptions,
  NinePointRefusal,
  NinePointResult,
} from './ninePointSynthesis';
