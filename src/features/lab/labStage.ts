import { LAB_METHODS } from '../../study/workPrecision';
import type { SweepMethod } from '../../solver/types';
import type { LabMessages } from './labMessages';
import { shownTol } from './workPrecisionChart';
import type { Messages } from '../../shared/i18n/messages';

/** The strings the lab's progress line needs: the method names and the lab's own. */
export type LabStageMessages = Pick<Messages, 'methodNames'> & LabMessages;

/**
 * A stage of the lab's study, read from the English text the study reports
 * (src/study/workPrecision.ts runWorkPrecision: 'reference', '<label>', '<label>, tol <tol>',
 * 'timing <k>/<n>: <label>[, tol <tol>]', 'done'). Anything else is kept as text.
 */
export type LabStage =
  | { kind: 'idle' }
  | { kind: 'reference' }
  | { kind: 'solve'; method: SweepMethod; tol: number | null }
  | { kind: 'timing'; pass: number; passes: number; method: SweepMethod; tol: number | null }
  | { kind: 'done' }
  | { kind: 'other'; text: string };

/** The lab's progress as the panel shows it: running with a stage and fraction, or finished, cancelled or failed. */
export interface LabProgressView {
  running: boolean;
  /** Fraction done in [0, 1] and the stage text while running. */
  progress: { fraction: number; stage: string } | null;
  cancelled: boolean;
  error: string | null;
  hasResult: boolean;
}

function methodAndTol(text: string): { method: SweepMethod; tol: number | null } | null {
  const m = /^(.*?)(?:, tol (\S+))?$/.exec(text);
  if (!m) return null;
  const method = LAB_METHODS.find((x) => x.label === m[1]);
  if (!method) return null;
  if (m[2] === undefined) return { method: method.method, tol: null };
  const tol = Number(m[2]);
  return Number.isFinite(tol) ? { method: method.method, tol } : null;
}

/** Reads a stage text reported by the lab; never throws ('other' for text it does not know). */
export function parseLabStage(text: string): LabStage {
  if (text === '') return { kind: 'idle' };
  if (text === 'reference') return { kind: 'reference' };
  if (text === 'done') return { kind: 'done' };
  const timing = /^timing (\d+)\/(\d+): (.*)$/.exec(text);
  if (timing) {
    const mt = methodAndTol(timing[3]);
    if (mt) return { kind: 'timing', pass: Number(timing[1]), passes: Number(timing[2]), ...mt };
  }
  const mt = methodAndTol(text);
  return mt ? { kind: 'solve', ...mt } : { kind: 'other', text };
}

function tolText(tol: number | null): string | null {
  return tol === null ? null : shownTol(tol);
}

/** The stage in the UI's language, with the method's translated name; unknown text is shown as it came. */
export function labStageText(stage: LabStage, t: LabStageMessages): string {
  switch (stage.kind) {
    case 'idle':
      return '';
    case 'reference':
      return t.labStageReference;
    case 'done':
      return t.labStageDone;
    case 'solve':
      return t.labStageSolve(t.methodNames[stage.method], tolText(stage.tol));
    case 'timing':
      return t.labStageTiming(
        String(stage.pass),
        String(stage.passes),
        t.labStageSolve(t.methodNames[stage.method], tolText(stage.tol)),
      );
    case 'other':
      return stage.text;
  }
}

/**
 * What the progress bar says and shows: its accessible value text and its value in [0, 100]. Running gives the
 * translated stage and percent; otherwise failed, cancelled, finished or not run yet, in that order of precedence.
 */
export function labProgressStatus(lab: LabProgressView, t: LabStageMessages): { text: string; percent: number } {
  if (lab.running) {
    const percent = Math.round(Math.min(1, Math.max(0, lab.progress?.fraction ?? 0)) * 100);
    // Before the first report the study is starting on its first stage, the reference solution.
    const stage = labStageText(parseLabStage(lab.progress?.stage ?? ''), t) || t.labStageReference;
    return { text: t.labProgress(stage, String(percent)), percent };
  }
  if (lab.error) return { text: t.labStatusFailed, percent: 0 };
  if (lab.cancelled) return { text: t.labStatusCancelled, percent: lab.hasResult ? 100 : 0 };
  if (lab.hasResult) return { text: t.labStatusDone, percent: 100 };
  return { text: t.labStatusIdle, percent: 0 };
}
