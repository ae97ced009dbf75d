import type { Locale } from '../../shared/state/appState';
import type { HardCaseId } from './hardCases';
import { labMessagesEn } from './labMessagesEn';
import { labMessagesZhTw } from './labMessagesZhTw';
import { messageModule } from '../../shared/i18n/messageModule';

/**
 * The solver lab's strings, apart from the app's (shared/i18n/messages.ts): only the lab page reads them, so they load
 * with it, both languages together, and the simulator's first load does not carry them.
 */
export interface LabMessages {
  /** Short names of the hard cases (lab presets). */
  hardCaseNames: Record<HardCaseId, string>;
  /** One sentence per hard case: what makes it hard. */
  hardCaseNotes: Record<HardCaseId, string>;
  labTitle: string;
  labIntro: string;
  labRerun: string;
  labCancel: string;
  /** Progress line; percent is a formatted number without the % sign. */
  labProgress: (stage: string, percent: string) => string;
  labCancelled: string;
  /** Stages of the lab's study as the progress line names them (see features/lab/labStage.ts). */
  labStageReference: string;
  labStageSolve: (method: string, tol: string | null) => string;
  labStageTiming: (pass: string, passes: string, what: string) => string;
  labStageDone: string;
  /** Short states of the lab's progress bar (its accessible value text). */
  labStatusIdle: string;
  labStatusDone: string;
  labStatusCancelled: string;
  labStatusFailed: string;
  labStep: string;
  labMethod: string;
  labTolerance: string;
  labToleranceDefault: string;
  labTableHeaders: {
    method: string;
    nsPerPoint: string;
    itersPerPoint: string;
    maxError: string;
    p99Error: string;
    failed: string;
    wrongBranch: string;
    falseConvergence: string;
  };
  labDiagramTitle: string;
  labDiagramX: string;
  labDiagramY: string;
  /** Legend entry for the diamond marking a method's default settings. */
  labLegendDefault: string;
  /** Legend entry for the red outline of configurations that failed somewhere on the cycle. */
  labLegendFailed: string;
  /** Tooltip of one diagram point; all arguments already formatted. */
  labPointTooltip: (method: string, tol: string, nsPerPoint: string, maxError: string) => string;
  labCycleTitle: string;
  labCycleIterations: string;
  labCycleDetJ: string;
  labNearestLimit: (deg: string, atDeg: string) => string;
  labNoLimit: string;
  labMinSin: (value: string, atDeg: string) => string;
  labHardCases: string;
  labHardCasesIntro: string;
  labChooseNote: string;
  exportLabPng: string;
  exportLabCsv: string;
  labWhatItMeans: string;
}

/** The lab's strings in every language (both bundled with the lab's chunk). */
export const labMessages = messageModule<LabMessages>(labMessagesEn, { 'zh-TW': labMessagesZhTw });

/** The lab's strings in a language. */
export function labMessagesFor(locale: Locale): LabMessages {
  return labMessages.get(locale);
}
