import { wrapDeg360 } from '../../solver/angles';
import type { Branch, Linkage, SweepMethod } from '../../solver/types';

/** UI languages: English (default) and Traditional Chinese. */
export type Locale = 'en' | 'zh-TW';

/** Which start the NR convergence plot and panel show: the previous cycle point or a fixed cold guess. */
export type NrStart = 'continuation' | 'cold';

/** How the angle plots are laid out: theta3 and theta4 in two charts, or both in one. */
export type PlotLayout = 'separate' | 'together';

/** Which plots the plot area shows: output angles, angular velocities or angular accelerations against theta2. */
export type PlotKind = 'angles' | 'velocities' | 'accelerations';

/** Which page the app shows: the simulator, or the solver lab (work-precision study of the current linkage). */
export type Page = 'simulator' | 'lab';

/** Direction of the animated input: +1 counter-clockwise (theta2 increasing), -1 clockwise. */
export type Direction = 1 | -1;

/** Coupler point P on the coupler plane: distance from the crank pin A (length unit) and angle from AB (degrees, CCW). */
export interface CouplerPoint {
  distance: number;
  angleDeg: number;
}

/** User pan and zoom on top of the automatic fit: zoom factor (1 = fitted), pan as fractions of the view's width and height. */
export interface ViewOffset {
  zoom: number;
  panX: number;
  panY: number;
}

/** The whole shareable state of the simulator; lengths in one user unit, angles in degrees. */
export interface AppState {
  linkage: Linkage;
  /** Input angle in degrees, kept in [0, 360). */
  theta2Deg: number;
  branch: Branch;
  coupler: CouplerPoint;
  playing: boolean;
  /** Animation speed in degrees per frame at a nominal 60 frames per second (0.5 to 10). */
  speedDegPerFrame: number;
  direction: Direction;
  showGrid: boolean;
  showAngles: boolean;
  showGhost: boolean;
  showTrace: boolean;
  /** Canvas: faint outlines of the two dead-centre poses and the rocker's swing arc (crank-rockers). */
  showDeadCentres: boolean;
  /** Canvas: instant centres I13 and I24 with their construction lines. */
  showInstantCentres: boolean;
  /** Velocity arrows at A, B and P on the canvas. */
  showVelocity: boolean;
  /** Acceleration arrows at A, B and P on the canvas. */
  showAcceleration: boolean;
  /** The plots shown below the canvas (default 'angles'). */
  plotKind: PlotKind;
  nrStart: NrStart;
  plotLayout: PlotLayout;
  /** Intervals per cycle: the sweep has samples + 1 points from 0 to 360 degrees. */
  samples: number;
  locale: Locale;
  view: ViewOffset;
  /** Method of the cycle sweep and of the NR runs shown at the current theta2 (chosen in the solver lab). */
  method: SweepMethod;
  /** NR tolerance for the chosen method; null = the method's default (full precision; 1e-9 absolute for seed). */
  tol: number | null;
  page: Page;
  /** Input step of the solver lab's cycle, degrees. */
  labStepDeg: number;
  /** Input crank angular velocity for the rate analysis, rad/s, counter-clockwise positive (default 10). */
  omega2RadPerS: number;
  /** Input crank angular acceleration for the rate analysis, rad/s², counter-clockwise positive (default 0). */
  alpha2RadPerS2: number;
  /** Lower edge of the usable transmission-angle band, degrees in [0, 180), below muBandHiDeg (default 40). */
  muBandLoDeg: number;
  /** Upper edge of the usable transmission-angle band, degrees in (0, 180], above muBandLoDeg (default 140). */
  muBandHiDeg: number;
}

/** Nominal frame rate (frames per second) that converts degrees per frame into degrees per second. */
export const NOMINAL_FPS = 60;

/** Slowest and fastest animation speeds, degrees per frame. */
export const SPEED_MIN = 0.5;
export const SPEED_MAX = 10;
/** Step of the speed slider, degrees per frame: fine enough that typed speeds such as 0.75 sit on it. */
export const SPEED_STEP = 0.05;

/** Smallest and largest sample counts per cycle accepted from the UI or the URL. */
export const SAMPLES_MIN = 12;
export const SAMPLES_MAX = 36000;

/** Sample counts offered in the settings (intervals per cycle). */
export const SAMPLE_CHOICES: readonly number[] = [360, 720, 1800, 3600];

/**
 * The report's linkage: r1 = 6, r2 = 2, r3 = 5, r4 = 5, theta2 = 45 deg, open branch, P at 2.5 and 30 deg;
 * input motion 10 rad/s without acceleration; transmission band 40 to 140 deg.
 */
export const DEFAULT_STATE: AppState = {
  linkage: { r1: 6, r2: 2, r3: 5, r4: 5 },
  theta2Deg: 45,
  branch: 'open',
  coupler: { distance: 2.5, angleDeg: 30 },
  playing: false,
  speedDegPerFrame: 1,
  direction: 1,
  showGrid: true,
  showAngles: true,
  showGhost: true,
  showTrace: true,
  showDeadCentres: false,
  showInstantCentres: false,
  showVelocity: false,
  showAcceleration: false,
  plotKind: 'angles',
  nrStart: 'continuation',
  plotLayout: 'separate',
  samples: 360,
  locale: 'en',
  view: { zoom: 1, panX: 0, panY: 0 },
  method: 'newton',
  tol: null,
  page: 'simulator',
  labStepDeg: 1,
  omega2RadPerS: 10,
  alpha2RadPerS2: 0,
  muBandLoDeg: 40,
  muBandHiDeg: 140,
};

/** Wraps degrees into [0, 360); non-finite input gives 0. Kept as the state's name for the units module's wrap. */
export const normalizeTheta2Deg = wrapDeg360;

/** Clamps x into [lo, hi]. */
export function clamp(x: number, lo: number, hi: number): number {
  return Math.min(hi, Math.max(lo, x));
}

/** The boolean display toggles of the state. */
export type ViewFlag =
  | 'showGrid'
  | 'showAngles'
  | 'showGhost'
  | 'showTrace'
  | 'showDeadCentres'
  | 'showInstantCentres'
  | 'showVelocity'
  | 'showAcceleration';

/** Every state change the UI can make. */
export type Action =
  | { type: 'setLength'; field: keyof Linkage; value: number }
  | { type: 'setLinkage'; linkage: Linkage }
  | { type: 'setTheta2'; deg: number }
  | { type: 'setBranch'; branch: Branch }
  | { type: 'toggleBranch' }
  | { type: 'setCoupler'; coupler: Partial<CouplerPoint> }
  | { type: 'setPlaying'; playing: boolean }
  | { type: 'setSpeed'; degPerFrame: number }
  | { type: 'setDirection'; direction: Direction }
  | { type: 'setFlag'; flag: ViewFlag; value: boolean }
  | { type: 'setNrStart'; start: NrStart }
  | { type: 'setPlotLayout'; layout: PlotLayout }
  | { type: 'setPlotKind'; kind: PlotKind }
  | { type: 'setSamples'; samples: number }
  | { type: 'setLocale'; locale: Locale }
  | { type: 'setView'; view: ViewOffset }
  | { type: 'animate'; theta2Deg: number; direction: Direction; branch: Branch }
  | { type: 'applyPreset'; linkage: Linkage; theta2Deg: number; branch: Branch; coupler: CouplerPoint }
  | { type: 'setMethod'; method: SweepMethod; tol: number | null }
  | { type: 'setPage'; page: Page }
  | { type: 'setLabStep'; stepDeg: number }
  | { type: 'setInputMotion'; omega2RadPerS?: number; alpha2RadPerS2?: number }
  | { type: 'setMuBand'; loDeg: number; hiDeg: number }
  | { type: 'replace'; state: AppState };

/** The app's reducer: pure, returns the same object when nothing changes. Assumes values were validated at the edge. */
export function reducer(state: AppState, action: Action): AppState {
  switch (action.type) {
    case 'setLength':
      if (state.linkage[action.field] === action.value) return state;
      return { ...state, linkage: { ...state.linkage, [action.field]: action.value } };
    case 'setLinkage':
      return { ...state, linkage: { ...action.linkage } };
    case 'setTheta2': {
      const deg = normalizeTheta2Deg(action.deg);
      return deg === state.theta2Deg ? state : { ...state, theta2Deg: deg };
    }
    case 'setBranch':
      return action.branch === state.branch ? state : { ...state, branch: action.branch };
    case 'toggleBranch':
      return { ...state, branch: state.branch === 'open' ? 'crossed' : 'open' };
    case 'setCoupler':
      return { ...state, coupler: { ...state.coupler, ...action.coupler } };
    case 'setPlaying':
      return action.playing === state.playing ? state : { ...state, playing: action.playing };
    case 'setSpeed':
      return { ...state, speedDegPerFrame: clamp(action.degPerFrame, SPEED_MIN, SPEED_MAX) };
    case 'setDirection':
      return { ...state, direction: action.direction };
    case 'setFlag':
      return state[action.flag] === action.value ? state : { ...state, [action.flag]: action.value };
    case 'setNrStart':
      return { ...state, nrStart: action.start };
    case 'setPlotLayout':
      return { ...state, plotLayout: action.layout };
    case 'setPlotKind':
      return action.kind === state.plotKind ? state : { ...state, plotKind: action.kind };
    case 'setSamples':
      return { ...state, samples: Math.round(clamp(action.samples, SAMPLES_MIN, SAMPLES_MAX)) };
    case 'setLocale':
      return { ...state, locale: action.locale };
    case 'setView':
      return { ...state, view: { ...action.view } };
    case 'animate': {
      const deg = normalizeTheta2Deg(action.theta2Deg);
      if (deg === state.theta2Deg && action.direction === state.direction && action.branch === state.branch)
        return state;
      return { ...state, theta2Deg: deg, direction: action.direction, branch: action.branch };
    }
    case 'applyPreset':
      return {
        ...state,
        linkage: { ...action.linkage },
        theta2Deg: normalizeTheta2Deg(action.theta2Deg),
        branch: action.branch,
        coupler: { ...action.coupler },
        view: { zoom: 1, panX: 0, panY: 0 },
      };
    case 'setMethod':
      if (action.method === state.method && action.tol === state.tol) return state;
      return { ...state, method: action.method, tol: action.tol };
    case 'setPage':
      return action.page === state.page ? state : { ...state, page: action.page, playing: false };
    case 'setLabStep':
      return action.stepDeg === state.labStepDeg ? state : { ...state, labStepDeg: action.stepDeg };
    case 'setInputMotion': {
      const omega2RadPerS = action.omega2RadPerS ?? state.omega2RadPerS;
      const alpha2RadPerS2 = action.alpha2RadPerS2 ?? state.alpha2RadPerS2;
      if (omega2RadPerS === state.omega2RadPerS && alpha2RadPerS2 === state.alpha2RadPerS2) return state;
      return { ...state, omega2RadPerS, alpha2RadPerS2 };
    }
    case 'setMuBand':
      // A band whose edges cross is refused (the state keeps lo < hi); the controls validate before dispatching.
      if (!(action.loDeg < action.hiDeg)) return state;
      if (action.loDeg === state.muBandLoDeg && action.hiDeg === state.muBandHiDeg) return state;
      return { ...state, muBandLoDeg: action.loDeg, muBandHiDeg: action.hiDeg };
    case 'replace':
      return action.state;
  }
}
