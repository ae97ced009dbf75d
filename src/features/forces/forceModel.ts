// The forces module itself, not the solver's barrel: the barrel would pull the sweep and NR into the main bundle.
import { degToRad } from '../../solver/angles';
import { linkForces } from '../../solver/forces';
import type { JointForces, LinkInertia, LinkInertias, Loads } from '../../solver/forces';
import type { InputMotion } from '../../solver/rates';
import type { Angles, Linkage } from '../../solver/types';
import type { AppState } from '../../shared/state/appState';
import { effectiveInputMotion } from '../../shared/state/inputMotion';
import type { ForcesState, LinkMassProps, MovingLink } from '../../shared/state/slices/forcesSlice';
import { MOVING_LINKS } from '../../shared/state/slices/forcesSlice';
import { METRES_PER_UNIT } from '../../shared/state/slices/designSlice';
import { slenderBar } from '../../shared/linkage/slenderBar';
import type { LengthUnit } from '../../shared/state/slices/designSlice';

/**
 * Everything the forces solver needs, in SI at the app's edge: the linkage and the coupler point in metres (the
 * state's lengths times METRES_PER_UNIT), the links' mass properties, the loads and the input motion (ω2 signed by
 * the animation direction, as the motion panel's rates).
 */
export interface ForceSetup {
  /** Lengths in metres. */
  linkage: Linkage;
  inertia: LinkInertias;
  loads: Loads;
  input: InputMotion;
  /** Coefficient of speed fluctuation for the flywheel. */
  k: number;
}

/** The link lengths of the crank, coupler and rocker (the state's unit). */
function linkLength(l: Linkage, link: MovingLink): number {
  return link === 'crank' ? l.r2 : link === 'coupler' ? l.r3 : l.r4;
}

/** A link's properties as the user gave them, in SI (the CG offset from the length unit to metres). */
function givenLink(p: LinkMassProps, metresPerUnit: number): LinkInertia {
  return {
    mass: p.massKg,
    inertia: p.inertiaKgM2,
    cg: { dist: p.cgDistance * metresPerUnit, angle: degToRad(p.cgAngleDeg) },
  };
}

/**
 * The three links' mass properties (SI) from the forces slice: uniform bars of rhoKgPerM along each link's line
 * (the coupler's bar runs A→B), or each link's own mass, inertia and CG.
 */
export function linkInertias(linkage: Linkage, unit: LengthUnit, f: ForcesState): LinkInertias {
  const perMetre = METRES_PER_UNIT[unit];
  const one = (link: MovingLink): LinkInertia =>
    f.massModel === 'bars'
      ? slenderBar(linkLength(linkage, link) * perMetre, f.rhoKgPerM)
      : givenLink(f[link], perMetre);
  return { crank: one('crank'), coupler: one('coupler'), rocker: one('rocker') };
}

/** The per-link values that match the bars now shown (seeds the per-link model when it is first chosen). */
export function barSeeds(linkage: Linkage, unit: LengthUnit, f: ForcesState): Record<MovingLink, LinkMassProps> {
  const perMetre = METRES_PER_UNIT[unit];
  const out = {} as Record<MovingLink, LinkMassProps>;
  for (const link of MOVING_LINKS) {
    const length = linkLength(linkage, link);
    const bar = slenderBar(length * perMetre, f.rhoKgPerM);
    out[link] = { massKg: bar.mass, inertiaKgM2: bar.inertia, cgDistance: length / 2, cgAngleDeg: 0 };
  }
  return out;
}

/** What a forces setup is made from: the lengths and coupler point, the forces slice and the input motion (an AppState is one). */
export interface ForceInputs {
  design: Pick<AppState['design'], 'linkage' | 'coupler' | 'lengthUnit'>;
  forces: AppState['forces'];
  motion: Pick<AppState['motion'], 'omega2RadPerS' | 'alpha2RadPerS2' | 'direction'>;
}

/** The state's forces setup in SI (see ForceSetup). */
export function forceSetup(state: ForceInputs): ForceSetup {
  const { design, motion, forces: f } = state;
  const perMetre = METRES_PER_UNIT[design.lengthUnit];
  const l = design.linkage;
  const linkage = { r1: l.r1 * perMetre, r2: l.r2 * perMetre, r3: l.r3 * perMetre, r4: l.r4 * perMetre };
  const g = f.gravityMPerS2;
  const loads: Loads = {
    // Straight down is -y exactly (the solver's default), without cos(-pi/2) g sideways.
    gravity: f.gravityAngleDeg === -90 ? { g } : { g, angle: degToRad(f.gravityAngleDeg) },
    couplerForce: {
      pDist: design.coupler.distance * perMetre,
      pAngle: degToRad(design.coupler.angleDeg),
      fx: f.pointForceXN,
      fy: f.pointForceYN,
    },
    outputTorque: f.loadTorqueNm,
  };
  return {
    linkage,
    inertia: linkInertias(l, design.lengthUnit, f),
    loads,
    input: effectiveInputMotion(motion.omega2RadPerS, motion.alpha2RadPerS2, motion.direction),
    k: f.speedFluctuation,
  };
}

/**
 * Why the forces at a pose are missing: no pose at theta2, a limit position (coupler and rocker in line), or an
 * overflow (finite rates, but a force past the double range, about 1.8e308).
 */
export type PoseForcesStatus = 'ok' | 'no-pose' | 'limit-position' | 'overflow';

/** The forces at one pose (SI) and sin μ there (the pin forces grow like 1 / |sin μ| near a toggle). */
export interface PoseForces {
  status: PoseForcesStatus;
  forces: JointForces | null;
  sinMu: number;
}

/** linkForces at theta2 (radians) and a solved pose (null: none) for the setup; NaN forces become a status. */
export function poseForces(setup: ForceSetup, theta2Rad: number, pose: Angles | null): PoseForces {
  if (!pose) return { status: 'no-pose', forces: null, sinMu: Number.NaN };
  const sinMu = Math.sin(pose.theta4 - pose.theta3);
  let forces: JointForces;
  try {
    forces = linkForces(setup.linkage, theta2Rad, pose, setup.input, setup.inertia, setup.loads);
  } catch {
    // The state holds validated values; a throw means a pose the solver does not take (a non-finite angle).
    return { status: 'no-pose', forces: null, sinMu };
  }
  if (forces.status === 'overflow') return { status: 'overflow', forces: null, sinMu };
  if (!Number.isFinite(forces.torque)) return { status: 'limit-position', forces: null, sinMu };
  return { status: 'ok', forces, sinMu };
}
