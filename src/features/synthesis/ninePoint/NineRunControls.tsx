import { formatNumber } from '../../../shared/format';
import { NINE_POINT_PATHS } from '../../../synthesis/ninePoint/ninePointSynthesis';
import { RunPanel } from '../path/RunPanel';
import type { NinePointMessages } from './ninePointMessages';
import type { NineRunState } from './useNinePointSynthesis';

/** Props of NineRunControls: the run, why it cannot run (or null), and its actions. */
export interface NineRunControlsProps {
  run: NineRunState;
  /** Why the targets cannot be solved (a sentence naming the points), or null when they can. */
  refusal: string | null;
  onRun: () => void;
  onCancel: () => void;
  nt: NinePointMessages;
}

/** Roots per tracked path: each path stands for an orbit of six (two labellings × three cognates). */
const ROOTS_PER_PATH = 6;

const count = (n: number) => String(n);

/** The run's status line (a live region), or null before the first run. */
function statusText(run: NineRunState, nt: NinePointMessages): string | null {
  const r = run.result;
  switch (run.status) {
    case 'running':
      return nt.statusRunning(run.workers);
    case 'cancelled': {
      const tracked = r ? r.paths.finished + r.paths.failed : 0;
      const total = r?.paths.total ?? NINE_POINT_PATHS;
      return nt.statusCancelled(
        count(tracked),
        count(total),
        count(tracked * ROOTS_PER_PATH),
        count(total * ROOTS_PER_PATH),
      );
    }
    case 'failed':
      return nt.statusFailed(run.error ?? '');
    case 'done':
      return r
        ? nt.statusDone(
            count(r.paths.finished),
            count(r.paths.total),
            count(r.paths.finished * ROOTS_PER_PATH),
            count(r.paths.total * ROOTS_PER_PATH),
            r.paths.failed,
            formatNumber(run.elapsedMs / 1000, 3),
            run.workers,
          ) + (r.paths.retracked ? nt.statusRetracked(r.paths.retracked) : '')
        : null;
    default:
      return null;
  }
}

/**
 * "Find every linkage" and "Cancel", the progress bar (role progressbar; its value text says the paths and roots
 * tracked: "700 of 1442 paths (4200 of 8652 roots)") and the status line.
 */
export function NineRunControls({ run, refusal, onRun, onCancel, nt }: NineRunControlsProps) {
  const running = run.status === 'running';
  const p = run.progress;
  const percent = p ? Math.round((100 * p.done) / p.total) : 0;
  const text = p
    ? nt.progressText(
        count(p.done),
        count(p.total),
        count(p.done * ROOTS_PER_PATH),
        count(p.total * ROOTS_PER_PATH),
        count(p.real),
      )
    : '';
  return (
    <RunPanel
      status={run.status}
      testId="nine-run"
      runLabel={nt.solve}
      cancelLabel={nt.cancel}
      runDisabled={refusal !== null || running}
      running={running}
      onRun={onRun}
      onCancel={onCancel}
      progress={{ percent, text, label: nt.progressLabel }}
      statusText={statusText(run, nt)}
      statusTestId="nine-status"
      notes={
        refusal ? (
          <p className="syn-error" role="alert" data-testid="nine-refusal">
            {refusal}
          </p>
        ) : null
      }
    />
  );
}
