import type { Locale } from '../../../shared/state/appState';
import { messageModule } from '../../../shared/i18n/messageModule';
import { ninePointMessagesEn } from './ninePointMessagesEn';
import { ninePointMessagesZhTw } from './ninePointMessagesZhTw';

/** The sort orders of the class list. */
export type NineSort = 'found' | 'size' | 'transmission';

/** The defects the numerics screen a class for (NinePointClass.defects). */
export type NineDefect = 'circuit' | 'order' | 'branch';

/**
 * The Nine points mode's strings (九點精確合成): only the synthesis page reads them, so they load with its chunk, both
 * languages together. Numbers arrive formatted; point numbers are 1-based.
 */
export interface NinePointMessages {
  intro: string;
  /** Not nine targets: how many there are. */
  needNine: (count: number) => string;
  /** Two targets at one place: their numbers and the place. */
  refusalCoincide: (i: number, j: number, x: string, y: string) => string;
  refusalLine: string;
  refusalCircle: string;
  /** The example button: WMS 1992 Problem 3's nine points. */
  exampleProblem3: string;
  solve: string;
  cancel: string;
  progressLabel: string;
  /** Paths and roots tracked so far of all, and the real roots found. */
  progressText: (done: string, total: string, roots: string, rootsTotal: string, real: string) => string;
  statusRunning: (workers: number) => string;
  /** A run that ended: paths and roots finished of all, the failed, seconds and workers. */
  statusDone: (
    finished: string,
    total: string,
    roots: string,
    rootsTotal: string,
    failed: number,
    seconds: string,
    workers: number,
  ) => string;
  /** A cancelled run: paths and roots tracked of all; the classes found so far stay. */
  statusCancelled: (tracked: string, total: string, roots: string, rootsTotal: string) => string;
  statusFailed: (why: string) => string;
  /** Added to statusDone when paths were tracked again because two had ended in one orbit (one jumped). */
  statusRetracked: (n: number) => string;
  /** "64 real linkage classes, 192 linkages". */
  classCount: (classes: number, linkages: number) => string;
  noClasses: string;
  classesTitle: string;
  filtersLegend: string;
  filterGrashof: string;
  filterCrank: string;
  filterNoDefect: string;
  /** The size bound: the longest link (or coupler offset) of some cognate at most this. */
  maxSizeLabel: string;
  maxSizeHelp: string;
  /** A refused bound: the text typed. */
  maxSizeError: (text: string) => string;
  sortLabel: string;
  sortText: Record<NineSort, string>;
  /** How many classes the filters leave. */
  shownCount: (shown: number, total: number) => string;
  noneMatch: string;
  className: (n: number) => string;
  /** A class's summary line pieces. */
  longestLink: string;
  crankInput: string;
  noCrank: string;
  defectsLabel: string;
  noDefects: string;
  defectText: Record<NineDefect, string>;
  /** The optimiser (Path mode) missed the same nine points by this much; the exact classes pass through them. */
  optimiserWorse: (distance: string) => string;
}

/** The Nine points mode's strings in every language. */
export const ninePointMessages = messageModule<NinePointMessages>(ninePointMessagesEn, {
  'zh-TW': ninePointMessagesZhTw,
});

/** The Nine points mode's strings in a language. */
export function ninePointMessagesFor(locale: Locale): NinePointMessages {
  return ninePointMessages.get(locale);
}
