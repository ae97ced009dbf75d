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
