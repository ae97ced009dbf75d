import { boolCodec, enumCodec, numberCodec } from '../../url/urlCodec';
import type { UrlKey, UrlTarget } from '../../url/urlKey';
import { nestedLens, optionalKey, sameText, sliceLens, urlKey } from '../../url/urlKey';
import { URL_VIEW_DIGITS } from '../../url/urlPrecision';
import type { Action } from '../appState';
import type { Slice } from '../slice';

/** How the angle plots are laid out: theta3 and theta4 in two charts, or both in one. */
export type PlotLayout = 'separate' | 'together';

/** The simulator's own plots: output angles, angular velocities or angular accelerations against theta2. */
export type MotionPlotKind = 'angles' | 'velocities' | 'accelerations';

/** The forces' plots (offered while Forces is on): input torque and pin-force magnitudes against theta2, the crank bearing's load. */
export type ForcePlotKind = 'torque' | 'pinForces' | 'bearing';

/** Which plots the plot area shows. */
export type PlotKind = MotionPlotKind | ForcePlotKind;

/** User pan and zoom on top of the automatic fit: zoom factor (1 = fitted), pan as fractions of the view's width and height. */
export interface ViewOffset {
  zoom: number;
  panX: number;
  panY: number;
}

/** The display slice: what the canvas and the plots show, and the view's pan and zoom. */
export interface DisplayState {
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
  plotLayout: PlotLayout;
  view: ViewOffset;
  /** Lower edge of the usable transmission-angle band, degrees in [0, 180), below muBandHiDeg (default 40). */
  muBandLoDeg: number;
  /** Upper edge of the usable transmission-angle band, degrees in (0, 180], above muBandLoDeg (default 140). */
  muBandHiDeg: number;
}

/** The boolean display toggles. */
export type ViewFlag =
  | 'showGrid'
  | 'showAngles'
  | 'showGhost'
  | 'showTrace'
  | 'showDeadCentres'
  | 'showInstantCentres'
  | 'showVelocity'
  | 'showAcceleration';

/** Actions only the display slice handles. */
export type DisplayAction =
  | { type: 'setFlag'; flag: ViewFlag; value: boolean }
  | { type: 'setPlotLayout'; layout: PlotLayout }
  | { type: 'setPlotKind'; kind: PlotKind }
  | { type: 'setView'; view: ViewOffset }
  | { type: 'setMuBand'; loDeg: number; hiDeg: number };

/** The fitted view with no pan or zoom. */
export const FITTED_VIEW: ViewOffset = { zoom: 1, panX: 0, panY: 0 };

/** Grid, angles, ghost and trace on; angle plots in two charts; transmission band 40 to 140 deg. */
export const DEFAULT_DISPLAY: DisplayState = {
  showGrid: true,
  showAngles: true,
  showGhost: true,
  showTrace: true,
  showDeadCentres: false,
  showInstantCentres: false,
  showVelocity: false,
  showAcceleration: false,
  plotKind: 'angles',
  plotLayout: 'separate',
  view: FITTED_VIEW,
  muBandLoDeg: 40,
  muBandHiDeg: 140,
};

/** The display slice's reducer: pure, returns the same object when nothing changes. */
export function displayReducer(s: DisplayState, action: Action): DisplayState {
  switch (action.type) {
    case 'setFlag':
      return s[action.flag] === action.value ? s : { ...s, [action.flag]: action.value };
    case 'setPlotLayout':
      return { ...s, plotLayout: action.layout };
    case 'setPlotKind':
      return action.kind === s.plotKind ? s : { ...s, plotKind: action.kind };
    case 'setView':
      return { ...s, view: { ...action.view } };
    case 'applyPreset':
      // A new linkage is drawn fitted: a pan or zoom chosen for the old one would frame the new one badly.
      return { ...s, view: FITTED_VIEW };
    case 'setMuBand':
      // A band whose edges cross is refused (the state keeps lo < hi); the controls validate before dispatching.
      if (!(action.loDeg < action.hiDeg)) return s;
      if (action.loDeg === s.muBandLoDeg && action.hiDeg === s.muBandHiDeg) return s;
      return { ...s, muBandLoDeg: action.loDeg, muBandHiDeg: action.hiDeg };
    default:
      return s;
  }
}

/** Zoom factors accepted from the URL (1 = fitted). */
export const ZOOM_RANGE = { min: 1e-3, max: 1e3 } as const;
/** Pan accepted from the URL, in fractions of the view's width or height. */
export const PAN_RANGE = { min: -100, max: 100 } as const;

const field = sliceLens('display');
const view = nestedLens('display', 'view');
const viewMoved = (u: UrlTarget): boolean => {
  const v = u.state.display.view;
  return v.zoom !== 1 || v.panX !== 0 || v.panY !== 0;
};
const flag = (name: string, f: ViewFlag): UrlKey<boolean> => urlKey(name, boolCodec, field(f));
const optionalFlag = (name: string, f: ViewFlag): UrlKey<boolean> =>
  optionalKey(name, boolCodec, field(f), DEFAULT_DISPLAY[f]);

/** The display's URL keys; z, px and py are written together when the view was zoomed or panned. */
export const DISPLAY_URL_KEYS: readonly UrlKey<unknown>[] = [
  flag('grid', 'showGrid'),
  flag('ang', 'showAngles'),
  flag('ghost', 'showGhost'),
  flag('trace', 'showTrace'),
  urlKey('plots', enumCodec(sameText(['separate', 'together'] as const)), field('plotLayout')),
  optionalFlag('vel', 'showVelocity'),
  optionalFlag('acc', 'showAcceleration'),
  optionalKey(
    'plot',
    enumCodec([
      ['ang', 'angles'],
      ['vel', 'velocities'],
      ['acc', 'accelerations'],
      ['trq', 'torque'],
      ['pin', 'pinForces'],
      ['brg', 'bearing'],
    ] as const),
    field('plotKind'),
    DEFAULT_DISPLAY.plotKind,
  ),
  optionalKey('mulo', numberCodec('muBandLo'), field('muBandLoDeg'), DEFAULT_DISPLAY.muBandLoDeg),
  optionalKey('muhi', numberCodec('muBandHi'), field('muBandHiDeg'), DEFAULT_DISPLAY.muBandHiDeg),
  optionalFlag('dc', 'showDeadCentres'),
  optionalFlag('ic', 'showInstantCentres'),
  urlKey('z', numberCodec(ZOOM_RANGE, { significant: URL_VIEW_DIGITS }), view('zoom'), 'state', viewMoved),
  urlKey('px', numberCodec(PAN_RANGE, { significant: URL_VIEW_DIGITS }), view('panX'), 'state', viewMoved),
  urlKey('py', numberCodec(PAN_RANGE, { significant: URL_VIEW_DIGITS }), view('panY'), 'state', viewMoved),
];

/** The display slice's registration in SLICES (appState.ts). */
export const DISPLAY_SLICE: Slice<DisplayState, DisplayAction> = {
  summary: 'what the canvas and the plots show: overlays, plot choice, view, transmission band',
  defaults: DEFAULT_DISPLAY,
  reducer: displayReducer,
  urlKeys: DISPLAY_URL_KEYS,
};
