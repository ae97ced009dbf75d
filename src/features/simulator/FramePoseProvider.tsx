import type { ReactNode } from 'react';
import { useMemo, useSyncExternalStore } from 'react';
import type { AppState } from '../../shared/state/appState';
import type { Playhead } from '../../shared/state/playhead';
import { withFrame } from '../../shared/state/playhead';
import { FramePoseContext } from '../../shared/linkage/FramePoseContext';
import { useFrameMotion } from './useFrameMotion';
import { useLinkagePose } from './useLinkagePose';

/** Props of FramePoseProvider: the committed state, Play's playhead, whether the ghost is on screen, the layout. */
export interface FramePoseProviderProps {
  state: AppState;
  playhead: Playhead;
  /** The other branch's pose is drawn (the canvas is on screen and the ghost is on). */
  ghostShown: boolean;
  children: ReactNode;
}

/**
 * Solves the frame on screen once (the state, or Play's playhead ahead of it) and provides it. It alone
 * subscribes to the playhead: per frame of Play only it and the views that read useFramePose re-render,
 * the children it was given stay as they are.
 */
export function FramePoseProvider({ state, playhead, ghostShown, children }: FramePoseProviderProps) {
  const frame = useSyncExternalStore(playhead.subscribe, playhead.get);
  const shown = useMemo(() => withFrame(state, frame), [state, frame]);
  const { local, marker } = useLinkagePose(shown, ghostShown);
  const motion = useFrameMotion(shown, local);
  const value = useMemo(() => ({ state: shown, local, marker, motion }), [shown, local, marker, motion]);
  return <FramePoseContext.Provider value={value}>{children}</FramePoseContext.Provider>;
}
