import { formatNumber, formatSci } from '../../../shared/format';
import type { SynthesisMessages } from '../synthesisMessages';
import { RunPanel } from './RunPanel';
import type { PathRunState } from './usePathSynthesis';

/** Props of RunControls: the run, whether there are targets, and its actions. */
export interface RunControlsProps {
  run: PathRunState;
  canRun: boolean;
  /** Why Synthesize waits (a field in error, a missing θ2), or null. */
  hold: string | null;
  /** The answers' summary when none passes close to every target (and why, where known), or null. */
  summary: string | null;
  onRun: () => void;
  onCancel: () => void;
  st: SynthesisMessages;
}

/** The run's status line (a live region), or null before the first run. */
function statusText(run: PathRunState, st: SynthesisMessages): string | null {
  switch (run.status) {
    case 'running':
      return st.statusRunning(run.workers);
    case 'cancelled':
      return st.statusCancelled;
    case 'stopping':
      return st.statusStopping;
    case 'stopped':
      return run.solutions && run.solutions.length > 0
        ? st.statusStopped(run.solutions.length, formatNumber(run.elapsedMs / 1000, 2), run.workers)
        : st.statusCancelled;
    case 'failed':
      return st.statusFailed(run.error ?? '');
    case 'done':
      return run.solutions && run.solutions.length > 0
        ? st.statusDone(run.solutions.length, formatNumber(run.elapsedMs / 1000, 2), run.workers)
        : st.statusNone;
    default:
      return null;
  }
}

/**
 * "Synthesize" (held while a field is in error) and "Stop", the progress bar (role progressbar; its value text is the best Σd² so far) and the
 * status line, with a summary when no answer passes close to every target.
 */
export function RunControls({ run, canRun, hold, summary, onRun, onCancel, st }: RunControlsProps) {
  const running = run.status === 'running';
  const p = run.progress;
  const percent = p ? Math.round(100 * p.fraction) : 0;
  const best = p && Number.isFinite(p.best) ? formatSci(p.best, 3) : '—';
  return (
    <RunPanel
      status={run.status}
      runLabel={st.synthesize}
      cancelLabel={st.cancel}
      runDisabled={!canRun || hold !== null || running}
      running={running}
      onRun={onRun}
      onCancel={onCancel}
      progress={{ percent, text: st.progressText(String(percent), best), label: st.progressLabel }}
      statusText={statusText(run, st)}
      statusTestId="synthesis-status"
      notes={
        <>
          {!canRun ? <p className="note">{st.needTargets}</p> : null}
          {canRun && hold ? (
            <p className="syn-error" data-testid="run-hold">
              {hold}
            </p>
          ) : null}
        </>
      }
    >
      {summary ? (
        <p className="syn-error" data-testid="no-fit-summary">
          {summary}
        </p>
      ) : null}
    </RunPanel>
  );
}
