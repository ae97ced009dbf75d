/**
 * Any planar linkage of pins (R) and sliders (P) with mobility 1: validation, Grübler–Kutzbach mobility, and
 * sweeps of poses, rates and forces by Newton–Raphson continuation on the constraint equations, plus templates
 * (docs/mechanism.md). Pure TypeScript: no DOM, React, d3 or worker globals. Radians, counter-clockwise.
 */
export type {
  JointSpec,
  LinkSeries,
  MechanismSpec,
  MechanismStatus,
  MechanismSweep,
  PointSeries,
  SliderSeries,
  TracerSpec,
} from './types';
export { GROUND, mobility, validateSpec, validateStructure } from './validate';
export { MAX_MOVE, MECHANISM_STATUSES, SINGULAR_PIVOT, sweepMechanism } from './sweep';
export {
  MECHANISM_TEMPLATES,
  chebyshevSpec,
  fourBarSpec,
  hoekensSpec,
  invertedSliderCrankSpec,
  jansenSpec,
  klannSpec,
  peaucellierSpec,
  pistonDrivenSpec,
  scotchYokeSpec,
  sliderCrankSpec,
  stephensonIIISpec,
  stephensonIISpec,
  stephensonISpec,
  wattIISpec,
  wattISpec,
  whitworthSpec,
} from './templates';
export type { MechanismTemplate } from './templates';
export { mechanismForces } from './forces';
export type { LinkMass, MechanismForces, MechanismLoads } from './forces';
