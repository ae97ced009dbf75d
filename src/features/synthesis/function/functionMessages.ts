import type { Locale } from '../../../shared/state/appState';
import { messageModule } from '../../../shared/i18n/messageModule';
import type { FunctionDefect, NoLinkageReason } from '../../../synthesis';
import type { Construct } from './expression';
import { functionMessagesEn } from './functionMessagesEn';
import { functionMessagesZhTw } from './functionMessagesZhTw';

/**
 * The Function mode's strings (函數生成): only the synthesis page reads them, so they load with its chunk, both
 * languages together. Numbers arrive formatted; every message about an expression names it.
 */
export interface FunctionMessages {
  intro: string;
  expressionLabel: string;
  expressionHelp: string;
  xFrom: string;
  xTo: string;
  theta2From: string;
  theta2To: string;
  theta4From: string;
  theta4To: string;
  precisionPoints: string;
  precisionNote: string;
  loadingParser: string;
  parserFailed: string;
  /** The expression named, then why it is refused. */
  expressionProblem: (expression: string, why: string) => string;
  why: {
    empty: string;
    long: (max: number) => string;
    character: (c: string) => string;
    /** math.js's own (English) message, and where it stopped (1-based character, null if it did not say). */
    syntax: (detail: string, char: number | null) => string;
    unknownName: (name: string) => string;
    unknownFunction: (name: string, allowed: string) => string;
    arguments: (name: string, count: number) => string;
    notAllowed: (what: string) => string;
  };
  constructs: Record<Construct, string>;
  notFinite: (expression: string, x: string) => string;
  sameEnds: (expression: string, y: string) => string;
  /** No linkage: why, then the turn of f (or ''), then the hint, each a sentence or sentences. */
  noLinkage: (why: string, turns: string, hint: string) => string;
  noLinkageWhy: Record<NoLinkageReason | 'other', string>;
  /** f turns back near x (a sentence, after the why). */
  noLinkageTurns: (x: string) => string;
  /** A range that gives a linkage: θ2 or θ4, its ends in degrees, clean (no defects). */
  noLinkageHint: (range: string, from: string, to: string, clean: boolean) => string;
  /** When none of the ranges tried gives a linkage. */
  noLinkageNoHint: string;
  /** A refused number: the field, the text, the value kept and why (null: not a number). */
  fieldError: (field: string, text: string, kept: string, why: string | null) => string;
  rangeWhy: { ends: string; within: (max: string) => string; span: (max: string) => string };
  pointsWhy: (max: number) => string;
  canvasLabel: string;
  /** Shown on the canvas when there is no design (the reason is with the fields). */
  noDesign: string;
  play: string;
  pause: string;
  xSlider: string;
  readout: (x: string, want: string, got: string) => string;
  designTitle: string;
  links: (r1: string, r2: string, r3: string, r4: string) => string;
  typeLine: (type: string) => string;
  branchLine: (branch: string) => string;
  maxError: (value: string, percent: string) => string;
  /** The largest error when some x cannot be reached (the not-assemblable defect says why). */
  maxErrorNone: string;
  /** f turns back near x on the range. */
  notMonotone: (x: string) => string;
  /** The largest error, as a percent of y's range, over the limit percent. */
  largeError: (percent: string, limit: string) => string;
  defectsTitle: string;
  defectWords: Record<FunctionDefect, string>;
  noDefects: string;
  precisionTitle: string;
  precisionCaption: string;
  columnX: string;
  columnTheta2: string;
  columnTheta4: string;
  columnError: string;
  errorChartTitle: string;
  errorChartX: string;
  errorChartY: string;
  errorSeries: string;
  precisionSeries: string;
  openInSimulator: string;
}

/** The Function mode's strings in every language (both bundled with the synthesis page's chunk). */
export const functionMessages = messageModule<FunctionMessages>(functionMessagesEn, { 'zh-TW': functionMessagesZhTw });

/** The Function mode's strings in a language. */
export function functionMessagesFor(locale: Locale): FunctionMessages {
  return functionMessages.get(locale);
}
