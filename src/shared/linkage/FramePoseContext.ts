import { createContext, useContext, useMemo, useSyncExternalStore } from 'react';
import type { ValueSource } from '../state/externalValue';
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
export type FramePoseSource = ValueSource<FramePose>;

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

/** The source of the frame on screen. Throws outside a FramePoseProvider. */
function useFramePoseSource(): FramePoseSource {
  const source = useContext(FramePoseContext);
  if (!source) throw new Error('useFramePose needs a FramePoseProvider above it');
  return source;
}

/** The frame on screen: the view re-renders every frame of Play. Throws outside a FramePoseProvider. */
export function useFramePose(): FramePose {
  const source = useFramePoseSource();
  return useSyncExternalStore(source.subscribe, source.get);
}

/**
 * A part of the frame on screen: the view re-renders only when `select`'s answer changes (Object.is), not every
 * frame of Play. `select` returns a field or a primitive of the frame, never a new object (it would change every
 * call). Throws outside a FramePoseProvider.
 */
export function useFrameSelect<T>(select: (frame: FramePose) => T): T {
  const source = useFramePoseSource();
  return useSyncExternalStore(source.subscribe, () => select(source.get()));
}

/**
 * A value derived from the frame on screen, as a source a view hands on without re-rendering (a chart's marker
 * moves at each frame of Play while the view that made it stays as it is). `derive` runs once per frame read;
 * the source is the same object while `deps` are. Throws outside a FramePoseProvider.
 */
export function useFrameDerived<T>(derive: (frame: FramePose) => T, deps: readonly unknown[]): ValueSource<T> {
  const source = useFramePoseSource();
  // derive is the caller's inline function: its inputs are deps.
  return useMemo(() => derivedSource(source, derive), [source, ...deps]);
}

/** A source of derive(frame), computed once per frame read (stable between frames, as useSyncExternalStore needs). */
export function derivedSource<T>(source: FramePoseSource, derive: (frame: FramePose) => T): ValueSource<T> {
  let seen: FramePose | null = null;
  let value: T;
  return {
    get() {
      const frame = source.get();
      if (frame !== seen) {
        value = derive(frame);
        seen = frame;
      }
      return value;
    },
    subscribe: source.subscribe,
  };
}
