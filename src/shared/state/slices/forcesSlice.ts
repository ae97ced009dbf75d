import { boolCodec, enumCodec, numberCodec } from '../../url/urlCodec';
import { convertLength } from './designSlice';
import type { Codec } from '../../url/urlCodec';
import type { UrlKey, UrlTarget } from '../../url/urlKey';
import { nestedLens, optionalKey, sliceLens, urlKey } from '../../url/urlKey';
import { URL_ANGLE_DECIMALS } from '../../url/urlPrecision';
import type { Action } from '../appState';
import type { Slice } from '../slice';

/** How the links' mass is given: uniform slender bars of one mass per length, or each link's own properties. */
export type MassModel = 'bars' | 'links';

/** The three moving links, named as the solver's LinkInertias. */
export type MovingLink = 'crank' | 'coupler' | 'rocker';

/** The moving links in order: crank (r2), coupler (r3), rocker (r4). */
export const MOVING_LINKS: readonly MovingLink[] = ['crank', 'coupler', 'rocker'];

/**
 * One link's mass properties as the user gives them: mass (kg), moment of inertia about the CG (kg·m²), and the CG
 * at cgDistance (length unit) from the link's first joint (O2, A, O4) at cgAngleDeg (degrees CCW) from its line.
 */
export interface LinkMassProps {
  massKg: number;
  inertiaKgM2: number;
  cgDistance: number;
  cgAngleDeg: number;
}

/** The forces slice: whether forces are solved, the mass model, the loads, the force arrows. */
export interface ForcesState {
  /** Solve and show the forces (URL frc); default off, and nothing about forces is computed while off. */
  enabled: boolean;
  massModel: MassModel;
  /** Mass per length of the uniform bars, kg/m (URL rho); default 1. */
  rhoKgPerM: number;
  /** Per-link properties, used when massModel is 'links'. */
  crank: LinkMassProps;
  coupler: LinkMassProps;
  rocker: LinkMassProps;
  /** Gravity, m/s² (URL g, 0 turns it off); default 9.81. */
  gravityMPerS2: number;
  /** Direction gravity points, degrees CCW from +x (URL gd); default -90 (down, -y). */
  gravityAngleDeg: number;
  /** Force at the coupler point P, N (URL pfx, pfy); default 0. */
  pointForceXN: number;
  pointForceYN: number;
  /** Load torque on the rocker from the driven machine, N·m CCW + (URL tl); default 0. */
  loadTorqueNm: number;
  /** Pin-force arrows on the canvas (URL fv); default off. */
  showVectors: boolean;
  /** Coefficient of speed fluctuation the flywheel is sized for (URL cs), in (0, 1]; default 0.05. */
  speedFluctuation: number;
}

/** The fields a setForces patch may change (the links' properties go through setLinkMass). */
export type ForcesSettableFields = Omit<ForcesState, MovingLink>;

/** Actions only the forces slice handles. */
export type ForcesAction =
  | { type: 'setForces'; patch: Partial<ForcesSettableFields> }
  | { type: 'setLinkMass'; link: MovingLink; props: Partial<LinkMassProps> }
  /** Per-link properties, seeded with given values (say, the bars' own) when they are first chosen. */
  | { type: 'setMassModel'; model: MassModel; seed?: Record<MovingLink, LinkMassProps> };

/** A link of 1 kg, 0.01 kg·m², its CG at its first joint: the per-link values before any are given. */
export const DEFAULT_LINK_MASS: LinkMassProps = { massKg: 1, inertiaKgM2: 0.01, cgDistance: 0, cgAngleDeg: 0 };

/** Forces off; uniform bars of 1 kg/m; g = 9.81 m/s² down; no point force or load torque; k = 0.05. */
export const DEFAULT_FORCES: ForcesState = {
  enabled: false,
  massModel: 'bars',
  rhoKgPerM: 1,
  crank: DEFAULT_LINK_MASS,
  coupler: DEFAULT_LINK_MASS,
  rocker: DEFAULT_LINK_MASS,
  gravityMPerS2: 9.81,
  gravityAngleDeg: -90,
  pointForceXN: 0,
  pointForceYN: 0,
  loadTorqueNm: 0,
  showVectors: false,
  speedFluctuation: 0.05,
};

/** Whether every field of patch already has its value in s. */
function unchanged<T extends object>(s: T, patch: Partial<T>): boolean {
  return (Object.keys(patch) as (keyof T)[]).every((k) => Object.is(s[k], patch[k]));
}

/** The forces slice's reducer: pure, returns the same object when nothing changes. */
export function forcesReducer(s: ForcesState, action: Action): ForcesState {
  switch (action.type) {
    case 'setForces':
      return unchanged(s, action.patch) ? s : { ...s, ...action.patch };
    case 'setLinkMass': {
      const cur = s[action.link];
      return unchanged(cur, action.props) ? s : { ...s, [action.link]: { ...cur, ...action.props } };
    }
    case 'setLengthUnit': {
      // The CG offsets are lengths: the same machine in the new unit.
      if (action.from === action.to) return s;
      const moved = (p: LinkMassProps) => ({ ...p, cgDistance: convertLength(p.cgDistance, action.from, action.to) });
      return { ...s, crank: moved(s.crank), coupler: moved(s.coupler), rocker: moved(s.rocker) };
    }
    case 'setMassModel': {
      if (action.model === s.massModel && !action.seed) return s;
      const seeded = action.seed
        ? { crank: { ...action.seed.crank }, coupler: { ...action.seed.coupler }, rocker: { ...action.seed.rocker } }
        : {};
      return { ...s, ...seeded, massModel: action.model };
    }
    default:
      return s;
  }
}

/** Largest mass (kg), inertia (kg·m²), force (N), torque (N·m) and CG offset (length unit) accepted from the URL. */
export const FORCES_LIMITS = { mass: 1e6, inertia: 1e9, force: 1e9, torque: 1e9, offset: 1e9, gravity: 1000 } as const;

const field = sliceLens('forces');
/** A forces key written only when its text differs from the default's. */
function optional<K extends keyof ForcesSettableFields>(
  name: string,
  codec: Codec<ForcesState[K]>,
  k: K,
): UrlKey<unknown> {
  return optionalKey(name, codec, field(k), DEFAULT_FORCES[k]);
}
const angleCodec = numberCodec({ min: -360, max: 360 }, { decimals: URL_ANGLE_DECIMALS });
const perLink = (u: UrlTarget): boolean => u.state.forces.massModel === 'links';

/** A link's four URL keys (m2, i2, c2, ca2 for the crank), written when the per-link model is chosen. */
function linkKeys(link: MovingLink, n: number): UrlKey<unknown>[] {
  const lens = nestedLens('forces', link);
  const key = (name: string, codec: Codec<number>, k: keyof LinkMassProps) =>
    urlKey(name, codec, lens(k), 'state', perLink);
  return [
    key(`m${n}`, numberCodec({ min: 0, max: FORCES_LIMITS.mass }), 'massKg'),
    key(`i${n}`, numberCodec({ min: 0, max: FORCES_LIMITS.inertia }), 'inertiaKgM2'),
    key(`c${n}`, numberCodec({ min: -FORCES_LIMITS.offset, max: FORCES_LIMITS.offset }), 'cgDistance'),
    key(`ca${n}`, angleCodec, 'cgAngleDeg'),
  ];
}

/**
 * The forces' URL keys, each written only when it differs from its default: frc, mass (bar | link), rho,
 * the per-link m2 i2 c2 ca2, m3 …, m4 … (only with mass=link), g, gd, pfx, pfy, tl, fv, cs.
 */
export const FORCES_URL_KEYS: readonly UrlKey<unknown>[] = [
  optional('frc', boolCodec, 'enabled'),
  optional(
    'mass',
    enumCodec([
      ['bar', 'bars'],
      ['link', 'links'],
    ] as const),
    'massModel',
  ),
  optional('rho', numberCodec({ min: 0, max: FORCES_LIMITS.mass }), 'rhoKgPerM'),
  ...linkKeys('crank', 2),
  ...linkKeys('coupler', 3),
  ...linkKeys('rocker', 4),
  optional('g', numberCodec({ min: 0, max: FORCES_LIMITS.gravity }), 'gravityMPerS2'),
  optional('gd', angleCodec, 'gravityAngleDeg'),
  optional('pfx', numberCodec({ min: -FORCES_LIMITS.force, max: FORCES_LIMITS.force }), 'pointForceXN'),
  optional('pfy', numberCodec({ min: -FORCES_LIMITS.force, max: FORCES_LIMITS.force }), 'pointForceYN'),
  optional('tl', numberCodec({ min: -FORCES_LIMITS.torque, max: FORCES_LIMITS.torque }), 'loadTorqueNm'),
  optional('fv', boolCodec, 'showVectors'),
  optional('cs', numberCodec({ min: 1e-6, max: 1 }), 'speedFluctuation'),
];

/** The forces slice's registration in SLICES (appState.ts). */
export const FORCES_SLICE: Slice<ForcesState, ForcesAction> = {
  summary: 'the forces: on or off, mass model, gravity, loads, force arrows',
  defaults: DEFAULT_FORCES,
  reducer: forcesReducer,
  urlKeys: FORCES_URL_KEYS,
};
