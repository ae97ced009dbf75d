import type { JobClientMode, JobClientModeReason } from './jobClient';
import { useMessages } from '../i18n/MessagesContext';
import { solverStatusText } from './useJobClient';

/** Props of SolverStatus: where the solver runs and why it left the worker. */
export interface SolverStatusProps {
  mode: JobClientMode;
  reason: JobClientModeReason | null;
}

/** A status line saying the worker was restarted or the solver runs on the main thread; nothing otherwise. */
export function SolverStatus({ mode, reason }: SolverStatusProps) {
  const t = useMessages();
  const text = solverStatusText(mode, reason, t);
  return text ? (
    <p className="note note-muted" role="status" data-testid="solver-status">
      {text}
    </p>
  ) : null;
}
