import { messageModule } from '../../shared/i18n/messageModule';
import type { MovingLink } from '../../shared/state/slices/forcesSlice';
import { forcesMessagesEn } from './forcesMessagesEn';

/** The pin forces the panel and the plots name: Fij is the force of link i on link j. */
export type PinForce = 'F12' | 'F32' | 'F43' | 'F14';

/** Why a cycle quantity is missing (solver ForceCycleStatus, and a crank at rest). */
export type CycleGap = 'crank-does-not-turn' | 'limit-position' | 'overflow' | 'omega-zero';

/**
 * The forces feature's strings, apart from the app's: English in the first load (the section's toggle and unit
 * show there), zh-TW a chunk loaded with the app's.
 */
export interface ForcesMessages {
  sectionForces: string;
  /** The toggle that turns the forces on (URL frc). */
  forcesToggle: string;
  massModel: string;
  massBars: string;
  massLinks: string;
  massPerLength: string;
  linkNames: Record<MovingLink, string>;
  mass: string;
  inertia: string;
  cgDistance: string;
  cgAngle: string;
  gravity: string;
  gravityAngle: string;
  gravityNote: string;
  pointForceX: string;
  pointForceY: string;
  loadTorque: string;
  forceVectors: string;
  speedFluctuation: string;
  /** A field's refusal: not a number, or outside [min, max]. */
  badNumber: (field: string, text: string) => string;
  outOfRange: (field: string, min: string, max: string) => string;
  settingsTitle: string;
  loadsTitle: string;
  /** Heading of the numbers at θ2 (formatted degrees, without the degree sign). */
  forcesAt: (theta2: string) => string;
  /** Exactly "Input torque T12". */
  inputTorque: string;
  pinForces: string;
  pinNames: Record<PinForce, string>;
  shakingForce: string;
  shakingMoment: string;
  /** A vector's direction, degrees counter-clockwise from +x. */
  directionDeg: (deg: string) => string;
  /** The reason the numbers are "—" at this pose. */
  limitReason: string;
  noPoseReason: string;
  /** A force at this pose passes the double range (status 'overflow'). */
  overflowReason: string;
  /** Near a toggle: μ in degrees and 1 / |sin μ|. */
  toggleNote: (muDeg: string, factor: string) => string;
  conventionNote: string;
  cycleTitle: string;
  meanTorque: string;
  rmsTorque: string;
  peakTorque: string;
  flywheelTitle: string;
  energyFluctuation: string;
  /** The flywheel inertia for coefficient k (formatted). */
  flywheelInertia: (k: string) => string;
  cycleGaps: Record<CycleGap, string>;
  plotTorque: string;
  plotPinForces: string;
  plotBearing: string;
  chartTorque: string;
  chartPinForces: string;
  chartBearing: string;
  axisTheta2: string;
  /** Axis labels with the plotted unit (N·m or kN·m, N or kN). */
  axisTorque: (unit: string) => string;
  axisForce: (unit: string) => string;
  axisFx: (unit: string) => string;
  axisFy: (unit: string) => string;
  legendMean: (value: string, unit: string) => string;
  plotFootnote: string;
  bearingFootnote: string;
  /** Buttons under a force plot: its PNG and SVG. */
  exportPng: string;
  exportSvg: string;
  exportWhat: (chart: string, format: string) => string;
  /** Canvas legend rows. */
  vectorBar: (value: string) => string;
  vectorZero: string;
  vectorClamped: string;
  vectorLimit: string;
}

/** The forces' strings: English bundled (the toggle shows in the first load), zh-TW loaded with the app's. */
export const forcesMessages = messageModule<ForcesMessages>(forcesMessagesEn, {
  'zh-TW': () => import('./forcesMessagesZhTw').then((m) => m.forcesMessagesZhTw),
});
