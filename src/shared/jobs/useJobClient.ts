import { useLayoutEffect, useState } from 'react';
import type { Messages } from '../i18n/messages';
import type { JobClient, JobClientMode, JobClientModeReason } from './jobClient';
import type { JobTable } from './jobTable';

/** A job client made by create() as it mounts and disposed on unmount, where it runs and why; null until mounted. */
export function useJobClient<T extends JobTable<T>>(
  create: (options: {
    onModeChange: (mode: JobClientMode, reason: JobClientModeReason | null, detail: string) => void;
  }) => JobClient<T>,
  name: string,
): { client: JobClient<T> | null; mode: JobClientMode; reason: JobClientModeReason | null } {
  const [client, setClient] = useState<JobClient<T> | null>(null);
  const [status, setStatus] = useState<{ mode: JobClientMode; reason: JobClientModeReason | null }>({
    mode: 'starting',
    reason: null,
  });
  // Made in the commit that mounts it (a layout effect), so the requests of the render that follows are posted in
  // that render's commit, not one render later.
  useLayoutEffect(() => {
    const c = create({
      onModeChange: (mode, reason, detail) => {
        setStatus({ mode, reason });
        if (mode === 'restarted' || mode === 'main-thread') console.warn(`${name}: ${detail}; now ${mode}.`);
      },
    });
    setClient(c);
    setStatus({ mode: c.mode, reason: c.reason });
    return () => c.dispose();
  }, [create, name]);
  return { client, ...status };
}

/** The status line for a solver mode, or null when the first worker is (or is about to be) solving. */
export function solverStatusText(
  mode: JobClientMode,
  reason: JobClientModeReason | null,
  t: Pick<Messages, 'solvingOnMainThread' | 'solverRestarted' | 'solverStoppedTwice'>,
): string | null {
  if (mode === 'restarted') return t.solverRestarted;
  if (mode === 'main-thread') return reason === 'stopped' ? t.solverStoppedTwice : t.solvingOnMainThread;
  return null;
}
