export { RECHECK_TOL, mergeNinePoint, ninePointSynthesis } from './ninePointSynthesis';
export type { NinePointClass, NinePointLinkage, NinePointOptions, NinePointResult } from './ninePointSynthesis';
