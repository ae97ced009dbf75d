import type { Locale } from '../../../shared/state/appState';
import { messageModule } from '../../../shared/i18n/messageModule';
import type { MotionDefect } from '../../../synthesis';
import { motionMessagesEn } from './motionMessagesEn';
import { motionMessagesZhTw } from './motionMessagesZhTw';

/**
 * The Motion mode's strings (運動生成): only the synthesis page reads them, so they load with its chunk, both
 * languages together. Numbers arrive formatted.
 */
export interface MotionMessages {
  intro: string;
  /** What the page does with this many poses (2 to 5; 6 for 6 to 20). */
  methodFor: Record<2 | 3 | 4 | 5 | 6, string>;
  posesTitle: string;
  poseName: (n: number) => string;
  tableCaption: string;
  columnX: string;
  columnY: string;
  columnAngle: string;
  addPose: string;
  removePose: (n: number) => string;
  removeColumn: string;
  /** A refused typed value: the cell named, the text echoed, the last value kept, and why (null: not a number). */
  cellError: (cell: string, text: string, kept: string, why: string | null) => string;
  /** Why a number is refused: it must be positive / lie in a range. */
  mustBePositive: string;
  mustBeBetween: (min: string, max: string) => string;
  canvasLabel: string;
  canvasHint: string;
  zoomIn: string;
  zoomOut: string;
  resetView: string;
  /** Screen-reader text for the selected pose (keyboard target). */
  selectedPose: (n: number, x: string, y: string, deg: string) => string;
  pivotLegend: string;
  pivotMoving: string;
  pivotFixed: string;
  pivotTable: (choice: 'moving' | 'fixed') => string;
  pivotName: Record<'A' | 'B' | 'O2' | 'O4', string>;
  constructionNote: (choice: 'moving' | 'fixed') => string;
  centreCurve: string;
  circleCurve: string;
  pickHint: string;
  picked: (n: number) => string;
  curvePoint: string;
  pickThis: string;
  clearPicks: string;
  burmesterPoints: (n: number) => string;
  fourBarsTitle: string;
  fourBarItem: (n: number, pairs: string) => string;
  /** Six or more poses: how many least-squares dyads, the list's title, an entry (dyads "1 + 3", rms error). */
  approxDyads: (n: number) => string;
  approxFourBarsTitle: string;
  approxItem: (n: number, pairs: string, rms: string) => string;
  /** The chosen four-bar's error at each pose: title, caption, columns. */
  errorsTitle: string;
  errorsCaption: string;
  columnPose: string;
  columnPositionError: string;
  columnAngleError: string;
  groundLength: string;
  groundAuto: (length: string) => string;
  timeRatio: string;
  poleNote: (x: string, y: string, rocker: string, swingDeg: string) => string;
  rockersTitle: string;
  rockerItem: (n: number, mu: string) => string;
  designTitle: string;
  links: (r1: string, r2: string, r3: string, r4: string) => string;
  typeLine: (type: string) => string;
  defectsTitle: string;
  defectWords: Record<MotionDefect, string>;
  defectShort: Record<MotionDefect, string>;
  noDefectsShort: string;
  /** The fixed pivots of the design shown, formatted. */
  pivotsLine: (o2x: string, o2y: string, o4x: string, o4y: string) => string;
  noDefects: string;
  shownAt: string;
  openInSimulator: string;
  problems: {
    collinear: (pivot: string) => string;
    coincident: string;
    degenerate: string;
    noRotation: string;
    halfTurn: string;
    atPole: string;
    noCrankPivot: (ground: string, rocker: string) => string;
    noBurmester: string;
    noApprox: string;
    /** Six or more poses: the least-squares fit found `found` (0 or 1) distinct dyads. */
    fewDyads: (found: number) => string;
    pickTwo: (picked: number) => string;
  };
}

/** The Motion mode's strings in every language (both bundled with the synthesis page's chunk). */
export const motionMessages = messageModule<MotionMessages>(motionMessagesEn, { 'zh-TW': motionMessagesZhTw });

/** The Motion mode's strings in a language. */
export function motionMessagesFor(locale: Locale): MotionMessages {
  return motionMessages.get(locale);
}
