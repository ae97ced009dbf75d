import { useSyncExternalStore } from 'react';
import type { SpatialBranchName } from '../../shared/state/slices/spatialSlice';
import type { SpatialPose } from '../../spatial';

/** What Play shows at one frame: θ2 (degrees), the branch, the pose and μ (radians) there (null where it cannot close). */
export interface SpatialFrame {
  theta2Deg: number;
  branch: SpatialBranchName;
  pose: SpatialPose | null;
  muRad: number | null;
}

/**
 * The frame on screen while Play runs, ahead of the app state (which gets θ2 and the branch when Play stops): a tiny
 * external store for useSyncExternalStore, so per frame only the views that follow it (numbers, plot markers, the θ2
 * field) re-render, not the page or the app. null when nothing plays ahead of the state.
 */
export class SpatialPlayhead {
  private frame: SpatialFrame | null = null;
  private readonly listeners = new Set<() => void>();

  /** The current frame or null; stable between sets. */
  readonly get = (): SpatialFrame | null => this.frame;

  /** Moves the playhead (null hands the view back to the state) and tells the subscribers. */
  set(frame: SpatialFrame | null): void {
    if (frame === this.frame) return;
    this.frame = frame;
    for (const listener of [...this.listeners]) listener();
  }

  /** Adds a change listener; returns its removal. */
  readonly subscribe = (listener: () => void): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };
}

/** The frame on screen: the playhead's while Play runs ahead of the state, else the state's own (base). */
export function useShownFrame(playhead: SpatialPlayhead, base: SpatialFrame): SpatialFrame {
  return useSyncExternalStore(playhead.subscribe, playhead.get) ?? base;
}
