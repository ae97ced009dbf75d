import type { ReactNode } from 'react';
import { useLayoutEffect, useMemo, useState, useSyncExternalStore } from 'react';
import type { AppState } from '../../shared/state/appState';
import type { Playhead } from '../../shared/state/playhead';
import { withFrame } from '../../shared/state/playhead';
import { FramePoseContext, createFramePoseSource } from '../../shared/linkage/FramePoseContext';
import { useFrameMotion } from './useFrameMotion';
import { useLinkagePose } from './useLinkagePose';
import { Theta2ScrubContext } from './theta2Scrub';
import type { Theta2Scrub } from './useAnimation';

/** Props of FramePoseProvider: the committed state, Play's playhead, whether the ghost is on screen, the layout. */
export interface FramePoseProviderProps {
  state: AppState;
  playhead: Playhead;
  /** The θ2 drag that moves the playhead (the θ2 slider and the canvas's crank pin take it from here). */
  scrub: Theta2Scrub;
  /** The other branch's pose is drawn (the canvas is on screen and the ghost is on). */
  ghostShown: boolean;
  children: ReactNode;
}

/**
 * Solves the frame on screen once (the state, or Play's playhead ahead of it) and provides it through a
 * FramePoseSource. It alone subscribes to the playhead: per frame of Play only it and the views that read
 * useFramePose re-render, the children it was given stay as they are. It also provides the θ2 drag (Theta2ScrubContext).
 */
export function FramePoseProvider({ state, playhead, scrub, ghostShown, children }: FramePoseProviderProps) {
  const frame = useSyncExternalStore(playhead.subscribe, playhead.get);
  const shown = useMemo(() => withFrame(state, frame), [state, frame]);
  const { local, marker } = useLinkagePose(shown, ghostShown);
  const motion = useFrameMotion(shown, local);
  const value = useMemo(
    () => ({ state: shown, local, marker, motion, committed: state, ghostShown }),
    [shown, local, marker, motion, state, ghostShown],
  );
  const [source] = useState(() => createFramePoseSource(value));
  // Held during the render, so that a reader mounting in this render reads this frame; told after the commit.
  source.set(value);
  useLayoutEffect(() => source.notify(), [source, value]);
  return (
    <Theta2ScrubContext.Provider value={scrub}>
      <FramePoseContext.Provider value={source}>{children}</FramePoseContext.Provider>
    </Theta2ScrubContext.Provider>
  );
}
