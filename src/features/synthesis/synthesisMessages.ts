import type { Locale } from '../../shared/state/appState';
import { messageModule } from '../../shared/i18n/messageModule';
import { synthesisMessagesEn } from './synthesisMessagesEn';
import { synthesisMessagesZhTw } from './synthesisMessagesZhTw';

/** Defects a path candidate can have, named in words on the page (see path/candidateFacts.ts). */
export type PathDefect = 'not-crank' | 'change-point' | 'toggle' | 'low-transmission' | 'misses';

/**
 * The synthesis page's strings (page shell and Path mode), apart from the app's: only the synthesis page reads them,
 * so they load with it, both languages together.
 */
export interface SynthesisMessages {
  pageTitle: string;
  pageIntro: string;
  /** The mode control's legend and its choices. */
  modeLegend: string;
  modePath: string;
  modeMotion: string;
  modeFunction: string;
  /** The exact nine-point mode (九點精確合成). */
  modeNine: string;
  /** Shown while a mode's code loads. */
  modeLoading: string;
  pathIntro: string;
  /** The targets canvas: name, hint and the empty state. */
  canvasLabel: string;
  canvasHint: string;
  canvasEmpty: string;
  /** The canvas's scale (one grid step, length unit) and the point under the pointer. */
  gridScale: (step: string) => string;
  cursorAt: (x: string, y: string) => string;
  zoomIn: string;
  zoomOut: string;
  resetView: string;
  targetsTitle: string;
  /** A target's name on the canvas and in the table (1-based). */
  targetName: (n: number) => string;
  tableX: string;
  tableY: string;
  tableTheta2: string;
  removeTarget: (n: number) => string;
  addTarget: string;
  clearTargets: string;
  exampleTargets: string;
  pasteLabel: string;
  pasteHelp: string;
  /** The paste's error: line number and the line's text. */
  pasteBadLine: (line: number, text: string) => string;
  pasteTooMany: (max: number) => string;
  badNumber: (text: string) => string;
  importCsv: string;
  exportCsv: string;
  importFailed: (why: string) => string;
  timingLegend: string;
  timingFree: string;
  timingStep: string;
  timingGiven: string;
  stepLabel: string;
  boundsTitle: string;
  boundLength: string;
  boundCoupler: string;
  pivotBox: string;
  pivotMin: string;
  pivotMax: string;
  /** The placeholder of a bound left to its default. */
  autoValue: (value: string) => string;
  inputLegend: string;
  inputCrank: string;
  inputAny: string;
  synthesize: string;
  cancel: string;
  needTargets: string;
  progressLabel: string;
  /** The progress bar's value text: percent done and the best Σd² so far. */
  progressText: (percent: string, best: string) => string;
  statusRunning: (workers: number) => string;
  statusCancelled: string;
  statusDone: (count: number, ms: string, workers: number) => string;
  statusNone: string;
  statusFailed: (why: string) => string;
  /** After Stop, while the candidates found so far are merged. */
  statusStopping: string;
  /** After Stop: candidates found before it, in seconds, on workers. */
  statusStopped: (count: number, ms: string, workers: number) => string;
  /** The candidates and the chosen design after the task was edited since the run. */
  staleResults: string;
  staleOpen: string;
  /** A bound's rule: the field's name. */
  mustBePositive: (field: string) => string;
  /** The pivot box's rule: the larger field's name, the smaller's, and the smaller's value. */
  mustBeMore: (more: string, less: string, lessValue: string) => string;
  stepRule: string;
  /** Synthesize waits: the names of the fields in error. */
  fieldsInError: (names: string) => string;
  /** Synthesize waits: the target (T3) with no θ2 under given timing. */
  missingTheta2: (target: string) => string;
  /** No candidate within 1 % of the targets' size (the size, formatted), and why where it is known. */
  noFit: (size: string) => string;
  reasonSpan: (reach: string, span: string) => string;
  reasonPivotFar: (target: string, distance: string, reach: string) => string;
  reasonSameTheta2: (a: string, b: string, theta2: string) => string;
  reasonUnknown: string;
  resultsTitle: string;
  /** One candidate's summary line (all numbers formatted). */
  candidateName: (rank: number) => string;
  errorSum: string;
  maxDistance: string;
  minTransmission: string;
  linkageType: string;
  defects: string;
  noDefects: string;
  defectText: Record<PathDefect, (value: string) => string>;
  grashof: string;
  nonGrashof: string;
  /** The type's note for a near-change-point design (S + L = P + Q), instead of Grashof. */
  changePoint: string;
  /** A candidate that is a Roberts cognate of an earlier one (its rank). */
  cognateOf: (rank: number) => string;
  chosenTitle: string;
  cognatesTitle: string;
  cognatesIntro: string;
  cognateOriginal: string;
  cognateName: (n: number) => string;
  lengths: (r1: string, r2: string, r3: string, r4: string) => string;
  openInSimulator: string;
  exportResultsCsv: string;
  exportSvg: string;
  exportPng: string;
  /** Words of the glossary the page uses (zh-TW: 路徑生成 …). */
  precisionPoints: string;
  structuralError: string;
  centerPointCurve: string;
  circlePointCurve: string;
  /** The page's print view (Ctrl+P or Print): one page with the task and the chosen result. */
  print: SynthesisPrintMessages;
}

/** Strings of the synthesis page's print view, shared by its four modes. */
export interface SynthesisPrintMessages {
  /** The button beside the mode control, and its note. */
  button: string;
  note: string;
  /** The sheet's heading (the mode's name in it) and its sections. */
  title: (mode: string) => string;
  task: string;
  result: string;
  figure: string;
  defects: string;
  /** No design to print yet (the task alone is printed). */
  noResult: string;
  /** Facts' labels. */
  lengthUnit: string;
  links: string;
  linkType: string;
  coupler: string;
  couplerValue: (distance: string, unit: string, angle: string) => string;
  placement: string;
  placementValue: (x: string, y: string, angle: string) => string;
  seed: string;
  bounds: string;
  boundsValue: (length: string, coupler: string) => string;
  pivotBoxValue: (xMin: string, xMax: string, yMin: string, yMax: string) => string;
  timingStepValue: (step: string) => string;
  candidate: string;
  /** Table columns: a target's given θ2, the design's θ2 there and its distance from the coupler point. */
  columnTarget: string;
  columnGiven: string;
  columnDesignTheta2: string;
  columnDistance: string;
}

/** The synthesis page's strings in every language (both bundled with the page's chunk). */
export const synthesisMessages = messageModule<SynthesisMessages>(synthesisMessagesEn, {
  'zh-TW': synthesisMessagesZhTw,
});

/** The synthesis page's strings in a language. */
export function synthesisMessagesFor(locale: Locale): SynthesisMessages {
  return synthesisMessages.get(locale);
}
