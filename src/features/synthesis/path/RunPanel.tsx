import type { ReactNode } from 'react';

/** The progress bar's figures: percent done, the value text (read out and shown on the bar) and its label. */
export interface RunProgress {
  percent: number;
  text: string;
  label: string;
}

/** Props of RunPanel: the run's state, the two buttons, the progress and the status line, and the notes around them. */
export interface RunPanelProps {
  /** The run's status, as data-status. */
  status: string;
  testId?: string;
  runLabel: string;
  cancelLabel: string;
  /** Whether the run button waits (no targets, a field in error, a refusal, a run going). */
  runDisabled: boolean;
  running: boolean;
  onRun: () => void;
  onCancel: () => void;
  /** Shown while running, or null. */
  progress: RunProgress | null;
  /** The status line (a live region), or null before the first run. */
  statusText: string | null;
  statusTestId: string;
  /** Under the buttons: why the run waits. */
  notes?: ReactNode;
  /** Under the status line: a summary of the answers. */
  children?: ReactNode;
}

/**
 * A synthesis mode's run card (the Path and Nine points modes): the run button and Cancel, what holds the run, the
 * progress bar (role progressbar, its value text read out) while it runs, and the status line.
 */
export function RunPanel(props: RunPanelProps) {
  const { status, running, progress } = props;
  return (
    <section className="card syn-card syn-run" data-status={status} data-testid={props.testId}>
      <div className="syn-buttons">
        <button type="button" className="btn btn-primary" disabled={props.runDisabled} onClick={props.onRun}>
          {props.runLabel}
        </button>
        <button type="button" className="btn" disabled={!running} onClick={props.onCancel}>
          {props.cancelLabel}
        </button>
      </div>
      {props.notes}
      {running && progress ? (
        <div
          className="syn-progress"
          role="progressbar"
          aria-label={progress.label}
          aria-valuemin={0}
          aria-valuemax={100}
          aria-valuenow={progress.percent}
          aria-valuetext={progress.text}
        >
          <div className="syn-progress-bar" style={{ width: `${progress.percent}%` }} />
          <span className="syn-progress-text">{progress.text}</span>
        </div>
      ) : null}
      <p className="status-line" role="status" data-testid={props.statusTestId}>
        {props.statusText}
      </p>
      {props.children}
    </section>
  );
}
