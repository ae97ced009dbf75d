/**
 * Spatial four-bars: the spherical four-bar (unit sphere, arcs in radians) and the RSSR linkage, their position
 * solves, exact rates, classification, output motion, sweeps and exports. Pure TypeScript: no DOM, React, d3 or
 * worker globals. Conventions (axes, pins, branch) in docs/spatial.md.
 */
export type {
  RSSRLinkage,
  SpatialBranch,
  SpatialClassification,
  SpatialInput,
  SpatialLinkageType,
  SpatialModel,
  SpatialPose,
  SphericalLinkage,
  Vec3,
} from './types';
export { solveSpherical } from './spherical';
export { solveRSSR } from './rssr';
export {
  SCAN_SAMPLES,
  classifyRSSR,
  classifySpherical,
  effectiveArcs,
  rssrInputRange,
  rssrOutputRange,
  sphericalInputRange,
  sphericalOutputRange,
} from './classify';
export { MOTION_SAMPLES, outputMotion, transmissionAngle } from './motion';
export type { OutputMotion, OutputSwing, SpatialDeadCentre } from './motion';
export { MAX_SPATIAL_STEPS, sphericalCouplerCurve, sweepSpatial } from './sweep';
export type { SpatialSweep, SweepSpatialOptions } from './sweep';
export {
  MAX_CSV_ROWS,
  SPATIAL_CSV_COLUMNS,
  SPATIAL_CSV_P_COLUMNS,
  SPATIAL_CSV_RATE_COLUMNS,
  spatialCsvRows,
} from './csv';
export type { SpatialCsv, SpatialCsvOptions } from './csv';
export { SPATIAL_PRESETS } from './presets';
export type { SpatialPreset } from './presets';
