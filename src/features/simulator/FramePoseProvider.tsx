import type { ReactNode } from 'react';
import { useLayoutEffect, useState } from 'react';
import type { AppState } from '../../shared/state/appState';
import type { Playhead } from '../../shared/state/playhead';
import { FramePoseContext, createFramePoseSource } from '../../shared/linkage/FramePoseContext';
import { Theta2ScrubContext } from './theta2Scrub';
import type { Theta2Scrub } from './useAnimation';
import { createFramePoser } from './framePoser';

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
 * FramePoseSource. It follows the playhead outside React: a frame of Play renders nothing here, only the views that
 * read the whole frame (useFramePose) or a part of it that changed (useFrameSelect), while the charts' markers follow
 * it by themselves (useFrameDerived). A new state or ghost renders it as usual. It also provides the θ2 drag
 * (Theta2ScrubContext).
 */
export function FramePoseProvider({ state, playhead, scrub, ghostShown, children }: FramePoseProviderProps) {
  const [poser] = useState(createFramePoser);
  // The frame for this render's state and the playhead as it is now (its later moves are followed below). Not a memo
  // of the state: a render for another reason after the playhead moved must not bring back an older frame; the
  // poser gives the same object for the same inputs.
  const value = poser(state, playhead.get(), ghostShown);
  const [source] = useState(() => createFramePoseSource(value));
  // Held during the render, so that a reader mounting in this render reads this frame; told after the commit.
  source.set(value);
  useLayoutEffect(() => source.notify(), [source, value]);
  useLayoutEffect(() => {
    const follow = () => {
      source.set(poser(state, playhead.get(), ghostShown));
      source.notify();
    };
    // A move between this render and this effect is shown at once.
    if (source.get() !== poser(state, playhead.get(), ghostShown)) follow();
    return playhead.subscribe(follow);
  }, [source, poser, state, playhead, ghostShown]);
  return (
    <Theta2ScrubContext.Provider value={scrub}>
      <FramePoseContext.Provider value={source}>{children}</FramePoseContext.Provider>
    </Theta2ScrubContext.Provider>
  );
}
