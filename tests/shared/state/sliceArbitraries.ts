import fc from 'fast-check';
import { SWEEP_METHODS } from '../../../src/solver/methods';
import type { AppState, Page, SliceName } from '../../../src/shared/state/appState';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import { OMEGA_UNITS } from '../../../src/shared/state/inputMotion';
import { LENGTH_UNITS } from '../../../src/shared/state/slices/designSlice';
import { DEFAULT_LINK_MASS, FORCES_LIMITS, MOVING_LINKS } from '../../../src/shared/state/slices/forcesSlice';
import { MAX_PATH_CHOICE, MAX_TARGETS } from '../../../src/shared/state/slices/synthesisSlice';
import {
  COORD_MAX,
  MAX_CHOICE,
  MAX_POSES,
  MAX_TIME_RATIO,
  MIN_POSES,
} from '../../../src/shared/state/slices/synMotionSlice';
import {
  EXPRESSION_CHARS,
  MAX_EXPRESSION_CHARS,
  MAX_FN_POINTS,
  RANGE_DEG_MAX,
  X_ABS_MAX,
} from '../../../src/shared/state/slices/synFunctionSlice';
import {
  MECH_FORCES_LIMITS,
  MECH_MAX_INPUT,
  MECH_MAX_SPEED,
  MECH_TEMPLATE_KEYS,
} from '../../../src/shared/state/slices/mechSlice';
import { MECHANISM_TEMPLATES } from '../../../src/mechanism';
import type { MechanismSpec } from '../../../src/mechanism';
import { SPATIAL_LENGTH_MAX } from '../../../src/shared/state/slices/spatialSlice';
import { ALPHA_ABS_MAX, OMEGA_ABS_MAX } from '../../../src/shared/ui/validateNumber';
import { LAB_STEPS_DEG, LAB_TOLERANCES } from '../../../src/study/options';

// Random states of every slice, on the grids their URL codecs write (angles to 1e-9°, the view to six digits, the
// synthesis page's lengths to ten), so that a state written to a link or a design file and read back is the same
// state. The table is keyed by SliceName: a slice added to SLICES without its generator here is a type error, so
// the round-trip properties (tests/shared/url/url.test.ts, tests/features/designs/designFile.test.ts) cover every
// key of every slice.

/** A finite double in [min, max]. */
const double = (min: number, max: number) => fc.double({ min, max, noNaN: true, noDefaultInfinity: true });

/** The nearest double to a decimal with `decimals` places in [lo, hi]: the URL's angle grid. */
export function onDecimalGrid(lo: number, hi: number, decimals: number): fc.Arbitrary<number> {
  const scale = 10 ** decimals;
  return fc.integer({ min: Math.ceil(lo * scale), max: Math.floor(hi * scale) }).map((k) => k / scale);
}

/** A double with at most `digits` significant digits in [lo, hi]: the view's and the synthesis page's grids. */
export function onSignificantGrid(lo: number, hi: number, digits: number): fc.Arbitrary<number> {
  return double(lo, hi)
    .map((x) => Number(x.toPrecision(digits)))
    .filter((x) => x >= lo && x <= hi);
}

/** Any length the design accepts (exact text in the URL). */
const length = double(1e-9, 1e9).filter((x) => x > 0);
/** An angle on the URL's grid in (−180, 180]. */
const angle180 = onDecimalGrid(-179.999999999, 180, 9);
/** Any finite coordinate (exact text). */
const coordinate = double(-1e9, 1e9);

const design: fc.Arbitrary<AppState['design']> = fc.record({
  linkage: fc.record({ r1: length, r2: length, r3: length, r4: length }),
  branch: fc.constantFrom('open' as const, 'crossed' as const),
  coupler: fc.record({ distance: double(0, 1e9), angleDeg: angle180 }),
  placement: fc.record({ x: coordinate, y: coordinate, angleDeg: angle180 }),
  lengthUnit: fc.constantFrom(...LENGTH_UNITS),
});

const motion: fc.Arbitrary<AppState['motion']> = fc.record({
  theta2Deg: onDecimalGrid(0, 359.999999999, 9),
  playing: fc.boolean(),
  speedDegPerFrame: double(0.5, 10),
  direction: fc.constantFrom(1 as const, -1 as const),
  omega2RadPerS: double(-OMEGA_ABS_MAX, OMEGA_ABS_MAX),
  alpha2RadPerS2: double(-ALPHA_ABS_MAX, ALPHA_ABS_MAX),
  omegaUnit: fc.constantFrom(...OMEGA_UNITS),
});

/** A transmission band lo < hi in [0, 180]. */
const band = fc
  .tuple(double(0, 180), double(0, 180))
  .filter(([a, b]) => a !== b)
  .map(([a, b]) => [Math.min(a, b), Math.max(a, b)] as const);

const display: fc.Arbitrary<AppState['display']> = fc
  .record({
    showGrid: fc.boolean(),
    showAngles: fc.boolean(),
    showGhost: fc.boolean(),
    showTrace: fc.boolean(),
    showDeadCentres: fc.boolean(),
    showInstantCentres: fc.boolean(),
    showVelocity: fc.boolean(),
    showAcceleration: fc.boolean(),
    plotKind: fc.constantFrom(
      'angles' as const,
      'velocities' as const,
      'accelerations' as const,
      'torque' as const,
      'pinForces' as const,
      'bearing' as const,
    ),
    plotLayout: fc.constantFrom('separate' as const, 'together' as const),
    view: fc.record({
      zoom: onSignificantGrid(0.001, 1000, 6),
      panX: onSignificantGrid(-100, 100, 6),
      panY: onSignificantGrid(-100, 100, 6),
    }),
    band,
  })
  .map(({ band: [lo, hi], ...s }) => ({ ...s, muBandLoDeg: lo, muBandHiDeg: hi }));

const solver: fc.Arbitrary<AppState['solver']> = fc.record({
  method: fc.constantFrom(...SWEEP_METHODS),
  tol: fc.constantFrom(null, ...LAB_TOLERANCES),
  nrStart: fc.constantFrom('continuation' as const, 'cold' as const),
  samples: fc.integer({ min: 12, max: 36000 }),
});

const shell: fc.Arbitrary<AppState['shell']> = fc.record({
  locale: fc.constantFrom('en' as const, 'zh-TW' as const),
  page: fc.constantFrom('simulator' as const, 'lab' as const, 'synthesis' as const),
});

const lab: fc.Arbitrary<AppState['lab']> = fc.record({ stepDeg: fc.constantFrom(...LAB_STEPS_DEG) });

const point = fc.record({ x: coordinate, y: coordinate });

/** A pivot box anywhere in the plane (off-centre too), min < max on both axes. */
const pivotBox = fc
  .tuple(coordinate, coordinate, coordinate, coordinate)
  .filter(([x0, y0, x1, y1]) => x0 !== x1 && y0 !== y1)
  .map(([x0, y0, x1, y1]) => ({
    min: { x: Math.min(x0, x1), y: Math.min(y0, y1) },
    max: { x: Math.max(x0, x1), y: Math.max(y0, y1) },
  }));

const synPath: fc.Arbitrary<AppState['synPath']> = fc.record({
  mode: fc.constantFrom('path' as const, 'motion' as const, 'function' as const),
  targets: fc.array(point, { maxLength: MAX_TARGETS }),
  timing: fc.constantFrom('free' as const, 'step' as const, 'given' as const),
  timingStepDeg: double(-180, 180).filter((x) => x !== 0),
  givenTheta2Deg: fc.array(double(-1e6, 1e6), { maxLength: MAX_TARGETS }),
  boundLength: fc.option(length, { nil: null }),
  boundCoupler: fc.option(length, { nil: null }),
  pivotBox: fc.option(pivotBox, { nil: null }),
  input: fc.constantFrom('crank' as const, 'any' as const),
  seed: fc.integer({ min: 1, max: 2 ** 31 - 1 }),
  // The candidate shown (URL cd): a rerun with the link's seed shows it again.
  chosen: fc.integer({ min: 0, max: MAX_PATH_CHOICE }),
});

const linkMass = fc.record({
  massKg: double(0, FORCES_LIMITS.mass),
  inertiaKgM2: double(0, FORCES_LIMITS.inertia),
  cgDistance: double(-FORCES_LIMITS.offset, FORCES_LIMITS.offset),
  cgAngleDeg: onDecimalGrid(-360, 360, 9),
});

const forces: fc.Arbitrary<AppState['forces']> = fc
  .record({
    enabled: fc.boolean(),
    massModel: fc.constantFrom('bars' as const, 'links' as const),
    rhoKgPerM: double(0, FORCES_LIMITS.mass),
    crank: linkMass,
    coupler: linkMass,
    rocker: linkMass,
    gravityMPerS2: double(0, FORCES_LIMITS.gravity),
    gravityAngleDeg: onDecimalGrid(-360, 360, 9),
    pointForceXN: double(-FORCES_LIMITS.force, FORCES_LIMITS.force),
    pointForceYN: double(-FORCES_LIMITS.force, FORCES_LIMITS.force),
    loadTorqueNm: double(-FORCES_LIMITS.torque, FORCES_LIMITS.torque),
    showVectors: fc.boolean(),
    speedFluctuation: double(1e-6, 1),
  })
  // The links' own properties are in the link only with mass=link; with bars they keep their defaults.
  .map((s) =>
    s.massModel === 'links'
      ? s
      : { ...s, ...Object.fromEntries(MOVING_LINKS.map((link) => [link, DEFAULT_LINK_MASS])) },
  );

/** A length of the synthesis page on its ten-digit grid, |v| ≤ max. */
const synLength = (max: number) => onSignificantGrid(-max, max, 10);
const synPoint = fc.record({ x: synLength(COORD_MAX), y: synLength(COORD_MAX) });

const synMotion: fc.Arbitrary<AppState['synMotion']> = fc.record({
  poses: fc.array(fc.record({ x: synLength(COORD_MAX), y: synLength(COORD_MAX), angleDeg: angle180 }), {
    minLength: MIN_POSES,
    maxLength: MAX_POSES,
  }),
  pivotChoice: fc.constantFrom('moving' as const, 'fixed' as const),
  pivots: fc.tuple(synPoint, synPoint),
  dyadPicks: fc.array(synPoint, { maxLength: 2 }),
  choice: fc.integer({ min: 0, max: MAX_CHOICE }),
  groundLength: fc.option(
    onSignificantGrid(0, COORD_MAX, 10).filter((x) => x > 0),
    { nil: null },
  ),
  timeRatio: onSignificantGrid(1, MAX_TIME_RATIO, 10),
});

/** A range's two ends on the ten-digit grid: different, within ±max, an angle range over at most a turn. */
function range(max: number, span: number): fc.Arbitrary<[number, number]> {
  return fc
    .tuple(onSignificantGrid(-max, max, 10), onSignificantGrid(-max, max, 10))
    .filter(([a, b]) => a !== b && Math.abs(b - a) <= span);
}

/** An expression's text as the URL keeps it: the allowed characters, trimmed, not empty. */
const expression = fc.oneof(
  fc.constantFrom('log10(x)', 'x^2', 'sin(x) + 1', 'exp(-x/2)', '1/x'),
  fc
    .string({ unit: fc.constantFrom(...'ax0189.+-*/^(), '), minLength: 1, maxLength: MAX_EXPRESSION_CHARS })
    .map((s) => s.trim())
    .filter((s) => s !== '' && EXPRESSION_CHARS.test(s)),
);

const synFunction: fc.Arbitrary<AppState['synFunction']> = fc.record({
  expression,
  xRange: range(X_ABS_MAX, Infinity),
  theta2RangeDeg: range(RANGE_DEG_MAX, RANGE_DEG_MAX),
  theta4RangeDeg: range(RANGE_DEG_MAX, RANGE_DEG_MAX),
  precisionPoints: fc.integer({ min: 3, max: MAX_FN_POINTS }),
});

/** Any text a person may type as a name (the separator *, %, spaces, CJK), made unique by a suffix. */
const anyName = fc.string({ unit: fc.constantFrom(...'aZ0_*%~ .-!中文'), minLength: 1, maxLength: 6 });

/**
 * An edited linkage: a template's, its joints renamed to any text (suffixed to stay unique), moved by any finite
 * offset, and its input sometimes unchosen (a linkage still being built).
 */
const mechSpec: fc.Arbitrary<MechanismSpec> = fc
  .tuple(
    fc.constantFrom(...MECH_TEMPLATE_KEYS),
    fc.array(anyName, { minLength: 20, maxLength: 20 }),
    fc.array(double(-1e6, 1e6), { minLength: 40, maxLength: 40 }),
    fc.boolean(),
  )
  .map(([key, names, offsets, noInput]) => {
    const spec = MECHANISM_TEMPLATES[key].spec;
    const rename = new Map(spec.joints.map((j, i) => [j.id, `${names[i % 20]}#${i}`]));
    return {
      ...spec,
      joints: spec.joints.map((j, i) => ({
        ...j,
        id: rename.get(j.id)!,
        x: j.x + offsets[(2 * i) % 40],
        y: j.y + offsets[(2 * i + 1) % 40],
      })),
      input: { joint: noInput ? '' : rename.get(spec.input.joint)! },
    };
  });

const mech: fc.Arbitrary<AppState['mech']> = fc.record({
  template: fc.constantFrom(...MECH_TEMPLATE_KEYS),
  spec: fc.option(mechSpec, { nil: null }),
  forces: fc.record({
    enabled: fc.boolean(),
    rhoKgPerM: double(0, MECH_FORCES_LIMITS.rho),
    gravityMPerS2: double(0, MECH_FORCES_LIMITS.gravity),
    inputSpeed: double(-MECH_FORCES_LIMITS.speed, MECH_FORCES_LIMITS.speed),
    joint: fc.oneof(fc.constant(''), anyName),
    arrows: fc.boolean(),
  }),
  // -0 is written as 0 (the state never needs to tell them apart).
  input: double(-MECH_MAX_INPUT, MECH_MAX_INPUT).map((x) => x + 0),
  direction: fc.constantFrom(1 as const, -1 as const),
  speed: double(1e-9, MECH_MAX_SPEED),
  // Traces and plots name joints as typed: any text, the empty list, or the default (null).
  traced: fc.option(fc.array(anyName, { maxLength: 6 }), { nil: null }),
  plots: fc.option(
    fc.tuple(
      fc.oneof(
        fc.constant(''),
        anyName.map((n) => `speed:${n}`),
      ),
      fc.oneof(fc.constant(''), anyName),
    ),
    { nil: null },
  ),
  velocities: fc.boolean(),
});

/** A value on the spatial page's degree grid (9 decimals) strictly inside (lo, hi) or in [lo, hi) as asked. */
const degrees = (lo: number, hi: number) => onDecimalGrid(lo, hi, 9);
/** Any RSSR length the spatial page accepts (exact text), from 1e-300 to 1e300. */
const spatialLength = double(1e-300, SPATIAL_LENGTH_MAX).filter((x) => x > 0);

const spatial: fc.Arbitrary<AppState['spatial']> = fc.record({
  kind: fc.constantFrom('sph' as const, 'rssr' as const),
  a1Deg: degrees(1e-9, 179.999999999),
  a2Deg: degrees(1e-9, 179.999999999),
  a3Deg: degrees(1e-9, 179.999999999),
  a4Deg: degrees(1e-9, 179.999999999),
  pDistDeg: degrees(0, 179.999999999),
  pAngleDeg: angle180,
  r2: spatialLength,
  r3: spatialLength,
  r4: spatialLength,
  a: fc.oneof(fc.constant(0), spatialLength),
  h2: double(-SPATIAL_LENGTH_MAX, SPATIAL_LENGTH_MAX),
  h4: double(-SPATIAL_LENGTH_MAX, SPATIAL_LENGTH_MAX),
  betaDeg: angle180,
  theta2Deg: degrees(0, 359.999999999),
  branch: fc.constantFrom('open' as const, 'crossed' as const),
  omega2RadPerS: fc.oneof(fc.constant(1), double(-1e6, 1e6)),
  alpha2RadPerS2: fc.oneof(fc.constant(0), double(-1e9, 1e9)),
});

/** One generator per slice of SLICES: a new slice without one here does not typecheck. */
export const SLICE_ARBITRARIES: { [K in SliceName]: fc.Arbitrary<AppState[K]> } = {
  design,
  motion,
  display,
  solver,
  shell,
  lab,
  synPath,
  forces,
  synMotion,
  synFunction,
  mech,
  spatial,
};

/**
 * The page whose links alone hold a slice's keys (UrlKey.page): its random states are on that page. The spatial
 * page's keys shadow the simulator's r2, r3, r4, t2, br, pd, pa and a2, so its state is only in page=3d links.
 */
export const SLICE_PAGE: Partial<Record<SliceName, Page>> = { spatial: 'spatial' };

/**
 * Any valid state a link can hold exactly: every field of every slice random, on the pages without keys of their own
 * (a slice of SLICE_PAGE at its default).
 */
export const anyLinkState: fc.Arbitrary<AppState> = fc
  .record(SLICE_ARBITRARIES)
  .map((s) => ({ ...s, spatial: DEFAULT_STATE.spatial }));

/**
 * Any valid state with one slice random and the others at their defaults (shrinks to the slice at fault); a slice of
 * SLICE_PAGE on its page.
 */
export function oneSliceState(name: SliceName): fc.Arbitrary<AppState> {
  const page = SLICE_PAGE[name];
  return (SLICE_ARBITRARIES[name] as fc.Arbitrary<unknown>).map(
    (slice) =>
      ({
        ...DEFAULT_STATE,
        ...(page ? { shell: { ...DEFAULT_STATE.shell, page } } : {}),
        [name]: slice,
      }) as AppState,
  );
}
