import type { Dispatch } from 'react';
import type { Action } from '../../shared/state/appState';
import { LAB_STEPS_DEG } from '../../study/options';
import { Segmented } from '../../shared/ui/Segmented';
import { useMessages } from '../../shared/i18n/MessagesContext';
import type { LabMessages } from './labMessages';
import { labProgressStatus } from './labStage';
import type { LabStudy } from './useLab';

/** Props of LabToolbar: the study's state and controls, the step, whether a client can run it, the lab's strings. */
export interface LabToolbarProps {
  lab: LabStudy & { run: () => void; cancel: () => void };
  stepDeg: number;
  canRun: boolean;
  lt: LabMessages;
  dispatch: Dispatch<Action>;
}

/** The study's step, Run/Re-run or Cancel, and its progress bar and status line. */
export function LabToolbar({ lab, stepDeg, canRun, lt, dispatch }: LabToolbarProps) {
  const t = useMessages();
  const hasResult = lab.result !== null;
  const status = labProgressStatus({ ...lab, hasResult }, { ...lt, methodNames: t.methodNames });
  return (
    <div className="lab-toolbar">
      <Segmented<string>
        legend={lt.labStep}
        value={String(stepDeg)}
        options={LAB_STEPS_DEG.map((s) => ({ value: String(s), label: `${s}°` }))}
        onChange={(v) => dispatch({ type: 'setLabStep', stepDeg: Number(v) })}
      />
      {lab.running ? (
        <button type="button" className="btn btn-small" onClick={lab.cancel}>
          {lt.labCancel}
        </button>
      ) : (
        <button type="button" className="btn btn-small btn-primary" onClick={lab.run} disabled={!canRun}>
          {hasResult ? lt.labRerun : t.labRun}
        </button>
      )}
      <div className="lab-progress">
        <progress max={100} value={status.percent} aria-label={lt.labTitle} aria-valuetext={status.text} />
        <span className="status-line" role="status" aria-live="polite">
          {lab.running ? status.text : lab.cancelled ? lt.labCancelled : (lab.error ?? '')}
        </span>
      </div>
    </div>
  );
}
