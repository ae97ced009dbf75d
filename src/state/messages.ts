import type { LinkageType, NewtonStatus, PointStatus } from '../solver/types';
import type { FieldError, FieldName } from './validate';
import type { PresetId } from './presets';

/** Every UI string of one language; functions take already formatted numbers (strings). */
export interface Messages {
  /** BCP 47 tag for the html lang attribute. */
  htmlLang: string;
  appTitle: string;
  appSubtitle: string;
  language: string;
  languageNames: { en: string; 'zh-TW': string };

  sectionLinks: string;
  sectionInput: string;
  sectionCoupler: string;
  sectionAnimation: string;
  sectionDisplay: string;
  sectionExport: string;
  sectionShare: string;
  sectionAnalysis: string;
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
  plotLayout: string;
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

  exportSize: string;
  sizeScreen: string;
  size2x: string;
  sizePrint: string;
  exportLinkage: string;
  exportTheta3: string;
  exportTheta4: string;
  exportBoth: string;
  exportConvergence: string;
  exportCsv: string;
  exportFailed: (reason: string) => string;

  copyLink: string;
  copyEmbed: string;
  copied: string;
  copyFailed: string;
  embedPanels: string;
  embedLock: string;
  panelNames: { controls: string; info: string; plots: string; export: string };
  lockLengths: string;
  lockAngle: string;
  openFull: string;
  embedTitle: string;

  errorTitle: string;
  errorBody: string;
  errorReset: string;
}
