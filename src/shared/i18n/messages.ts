import type { LinkageType, NewtonStatus, PointStatus, SweepMethod } from '../../solver/types';
import type { MotionPlotKind } from '../state/appState';
import type { OmegaUnit } from '../state/inputMotion';
import type { FieldError, FieldName } from '../ui/validateNumber';
import type { PresetId } from '../state/presets';
import type { EmbedPage } from '../url/embedOptions';

/** Every UI string of one language; functions take already formatted numbers (strings). */
export interface Messages {
  /** BCP 47 tag for the html lang attribute. */
  htmlLang: string;
  appTitle: string;
  appSubtitle: string;
  language: string;
  languageNames: { en: string; 'zh-TW': string };

  sectionLinks: string;
  /** The unit control beside the lengths (URL lu). */
  lengthUnit: string;
  /** One line under the unit: choosing one converts the lengths (the same linkage), forces are SI. */
  lengthUnitNote: string;
  sectionInput: string;
  sectionCoupler: string;
  sectionAnimation: string;
  sectionDisplay: string;
  sectionExport: string;
  /** Animation export (Export panel): the size group, 720p, frames, loop, buttons, progress, outcomes. */
  animationSize: string;
  size720p: string;
  framesPerCycle: string;
  animationLoop: string;
  exportGif: string;
  exportWebm: string;
  animationProgress: string;
  cancel: string;
  animationRunning: (done: number, total: number) => string;
  animationDone: (format: string) => string;
  animationCancelled: string;
  animationUnsupported: (reason: string) => string;
  framesOutOfRange: (min: number, max: number) => string;
  /** Vector export buttons. */
  exportLinkageSvg: string;
  exportTheta3Svg: string;
  exportTheta4Svg: string;
  exportBothSvg: string;
  exportOmegaSvg: string;
  exportAlphaSvg: string;
  exportConvergenceSvg: string;
  exportLabSvg: string;
  sectionShare: string;
  /** The Share panel's embed generator: its summary, size presets, lock names, preview and code labels. */
  embedGenerator: string;
  embedSize: string;
  embedPresetNames: { compact: string; standard: string; large: string; responsive: string };
  lockNames: {
    r1: string;
    r2: string;
    r3: string;
    r4: string;
    theta2: string;
    branch: string;
    coupler: string;
    play: string;
    template: string;
    edit: string;
    params: string;
  };
  /** The embed generator's page choice (the pages that embed, named as their tabs). */
  embedPage: string;
  /** The mechanism embed's table of joint positions (its accessible name). */
  embedPositions: string;
  embedPreview: string;
  embedCodeLabel: string;
  embedPreviewNote: string;
  sectionAnalysis: string;
  /** Design metrics panel (issue 10): transmission extremes, dead centres, swing, time ratio, input limits. */
  sectionDesign: string;
  designMuMin: string;
  designMuMax: string;
  /** Where an extreme or a dead centre occurs: "at θ2 = 44.415°". */
  designAt: (theta2: string) => string;
  deadCentreExtended: string;
  deadCentreFolded: string;
  /** The rocker angle at a dead centre: "θ4 = 101.537°". */
  deadCentreTheta4: (theta4: string) => string;
  swing: string;
  timeRatio: string;
  inputLimit: string;
  goTo: string;
  /** Accessible name of a go-to button: "Go to the extended dead centre (θ2 = 44.415°)". */
  goToLabel: (what: string, theta2: string) => string;
  noDeadCentres: string;
  muBand: string;
  muBandOrder: string;
  showDeadCentres: string;
  showInstantCentres: string;
  chartTransmission: string;
  axisMu: string;
  legendMu: string;
  legendOutsideBand: string;
  legendBand: (lo: string, hi: string) => string;
  /** Short chart labels of the dead-centre rules on θ2 axes. */
  markExtended: string;
  markFolded: string;
  /** Canvas label of the swing arc: "swing 48.54°". */
  swingLabel: (deg: string) => string;
  /** Canvas edge marker of an off-screen instant centre, with the length unit: "I13 (12.3, −4.5) m". */
  offscreenCentre: (name: string, x: string, y: string, unit: string) => string;
  /** Canvas label of an instant centre at infinity (its two lines are parallel), beside the arrow along them. */
  centreAtInfinity: (name: string) => string;
  sectionPlots: string;

  /** Accessible names of the fields and sliders; English ones begin with r1..r4 and θ2. */
  fieldLabels: Record<FieldName, string>;
  sliderSuffix: string;
  fieldShortNames: Record<FieldName, string>;
  fieldError: (e: FieldError, fmt: { raw: string; min: string; max: string }) => string;
  keepingLast: (value: string) => string;
  locked: string;

  branch: string;
  branchOpen: string;
  branchCrossed: string;
  play: string;
  pause: string;
  direction: string;
  ccw: string;
  cw: string;
  stepBack: string;
  stepForward: string;
  rockingNote: string;

  showGrid: string;
  showAngles: string;
  showGhost: string;
  showTrace: string;
  samples: string;

  preset: string;
  presetPlaceholder: string;
  presetNames: Record<PresetId, string>;

  grashofCheck: string;
  grashofYes: string;
  grashofNo: string;
  grashofChangePoint: string;
  linkageType: string;
  types: Record<LinkageType, string>;
  barker: string;
  inputRange: string;
  fullTurn: string;
  noRange: string;
  rangeInterval: (lo: string, hi: string) => string;
  /** An input range that passes through 0°, in the slider's [0, 360) convention: from lo up through 360°/0° to hi. */
  rangeWrapped: (lo: string, hi: string) => string;
  atTheta2: (theta2: string) => string;
  nrIterations: string;
  residual: string;
  detJ: string;
  status: string;
  newtonStatus: Record<NewtonStatus, string>;
  pointStatus: Record<PointStatus, string>;
  transmissionAngle: string;
  cycleSummary: (ok: string, total: string, iterations: string) => string;
  solvingOnMainThread: string;

  plotSeparate: string;
  plotTogether: string;
  /** Name of the separate/together toggle, for the plots it lays out (issue 19: it said 'Angle plots' over velocities). */
  plotLayout: Record<'angles' | 'velocities' | 'accelerations', string>;
  nrStartLabel: string;
  nrContinuation: string;
  nrCold: string;
  chartTheta3: string;
  chartTheta4: string;
  chartBoth: string;
  chartConvergence: (theta2: string) => string;
  axisTheta2: string;
  axisTheta3: string;
  axisTheta4: string;
  axisAngle: string;
  axisIteration: string;
  axisResidual: string;
  legendOtherBranch: string;
  angleFootnote: string;
  noConvergenceData: string;

  canvasLabel: string;
  cannotAssembleAt: (theta2: string) => string;
  cannotAssembleAny: string;
  reachableHint: (range: string) => string;
  resetView: string;
  zoomIn: string;
  zoomOut: string;
  gridSpacing: (step: string) => string;
  jointLabels: { O2: string; O4: string; A: string; B: string; P: string };

  /** Velocity and acceleration analysis (issue 9): input motion controls, panel, vectors, rate plots. */
  sectionMotion: string;
  omegaUnit: string;
  omegaUnits: Record<OmegaUnit, string>;
  showVelocity: string;
  showAcceleration: string;
  motionPanelTitle: string;
  motionAt: (theta2: string) => string;
  angularVelocity: string;
  angularAcceleration: string;
  pointSpeed: (point: string) => string;
  pointAcceleration: (point: string) => string;
  /** A vector's direction, counter-clockwise from the +x axis. */
  directionDeg: (deg: string) => string;
  limitPosition: string;
  motionNoPose: string;
  motionNote: string;
  plotKind: string;
  plotKinds: Record<MotionPlotKind, string>;
  chartRates: Record<'omega3' | 'omega4' | 'omegaBoth' | 'alpha3' | 'alpha4' | 'alphaBoth', string>;
  axisOmega: string;
  axisAlpha: string;
  rateFootnote: string;
  vectorVelocityBar: (value: string) => string;
  vectorAccelerationBar: (value: string) => string;
  vectorZero: string;
  vectorClamped: string;
  /** Units of the panel's point speeds and accelerations (the linkage's length unit per s, per s²). */
  unitSpeed: string;
  unitAcceleration: string;

  exportSize: string;
  sizeScreen: string;
  size2x: string;
  sizePrint: string;
  exportLinkage: string;
  exportTheta3: string;
  exportTheta4: string;
  exportBoth: string;
  /** The ω3-and-ω4 and α3-and-α4 plots (both links in one chart). */
  exportOmega: string;
  exportAlpha: string;
  exportConvergence: string;
  exportCsv: string;
  exportFailed: (reason: string) => string;
  /** Why a linkage export waits: the linkage view is not on screen for these lengths (the lab page is open). */
  exportNeedsLinkageView: string;

  copyLink: string;
  copyEmbed: string;
  copied: string;
  copyFailed: string;
  embedPanels: string;
  embedLock: string;
  panelNames: { controls: string; info: string; plots: string; export: string; forces: string };
  openFull: string;
  /** The widget's title (its title bar, the document's title, the snippet's iframe title), naming the page shown. */
  embedTitles: Record<EmbedPage, string>;

  errorTitle: string;
  errorBody: string;
  errorReset: string;
  /** Notice for a shared link with values that were ignored; list is already joined, count is how many. */
  urlIgnored: (list: string, count: number) => string;
  /** A synthesis canvas's exports: the picture as SVG and as PNG. */
  exportPictureSvg: string;
  exportPicturePng: string;
  /** The Share panel of the offline file (file:): why its links and embed code cannot work elsewhere. */
  offlineShare: string;
  /** Its one button: a link to this design in this file, on this computer. */
  copyLocalLink: string;
  /** The same notice for a <fourbar-lab> element, whose values come from its attributes, not a link. */
  attributesIgnored: (list: string, count: number) => string;
  /** One ignored parameter in that list (key and value already shortened). */
  urlIgnoredParam: (key: string, value: string) => string;
  /** Separator between ignored parameters in the list. */
  urlIgnoredSeparator: string;
  /** Tail of a long list: how many more were ignored. */
  urlIgnoredMore: (count: string) => string;
  urlNoticeDismiss: string;
  labRun: string;
  methodNames: Record<SweepMethod, string>;
  /** Status line: the solver worker stopped (missed its deadline or died) and was restarted. */
  solverRestarted: string;
  /** Status line: the worker stopped a second time, so the solver runs on the main thread. */
  solverStoppedTwice: string;
}
