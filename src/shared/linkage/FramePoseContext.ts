import { createContext, useContext, useSyncExternalStore } from 'react';
import type { AppState } from '../state/appState';
import type { PointResponse } from '../solution';
import type { FrameMotion } from './frameMotion';
import type { LocalPose } from './localPose';

/** The frame on screen: the state with Play's frame applied, its pose (main thread), the plots' marker and its motion. */
export interface FramePose {
  state: AppState;
  local: LocalPose;
  marker: PointResponse;
  /** Velocities and accelerations at the pose; null where it does not assemble. */
  motion: FrameMotion | null;
  /** The committed state (the frame's fields as the app state holds them, behind Play's playhead). */
  committed: AppState;
  /** The other branch's pose is drawn (the canvas is on screen and the ghost is on). */
  ghostShown: boolean;
}

/**
 * Where the frame on screen is read: its latest value, and a subscription to its changes. The context holds this
 * source, which stays the same object, rather than the frame: a context value that changes every frame of Play makes
 * React search the whole tree under the provider for its readers on every frame; a source's readers are found by
 * their subscriptions.
 */
export interface FramePoseSource {
  get(): FramePose;
  subscribe(listener: () => void): () => void;
}

/** A frame source: set(frame) holds the frame (read by get), notify() tells the readers. */
export function createFramePoseSource(first: FramePose): FramePoseSource & {
  set(frame: FramePose): void;
  notify(): void;
} {
  let frame = first;
  const listeners = new Set<() => void>();
  return {
    get: () => frame,
    set(next) {
      frame = next;
    },
    notify() {
      for (const listener of listeners) listener();
    },
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
  };
}

/** The source of the frame on screen; null outside a FramePoseProvider. */
export const FramePoseContext = createContext<FramePoseSource | null>(null);

/** The frame on screen (the views that follow every frame of Play read it). Throws outside a FramePoseProvider. */
export function useFramePose(): FramePose {
  const source = useContext(FramePoseContext);
  if (!source) throw new Error('useFramePose needs a FramePoseProvider above it');
  return useSyncExternalStore(source.subscribe, source.get);
}
