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
 * How often (ms) the panels (numbers, plot markers, the θ2 field) follow Play: each of their updates lays out and
 * repaints text and charts, which under a software compositor cost more than the 3D view's frame (docs/benchmarks.md,
 * Spatial), so they follow at about 12 per second while the view draws every frame.
 */
export const PANEL_INTERVAL_MS = 80;

/**
 * The frame on screen while Play runs, ahead of the app state (which gets θ2 and the branch when Play stops): a tiny
 * external store for useSyncExternalStore, so only the views that follow it (numbers, plot markers, the θ2 field)
 * re-render, not the page or the app, and those at most once per PANEL_INTERVAL_MS while Play advances. null when
 * nothing plays ahead of the state.
 */
export class SpatialPlayhead {
  private frame: SpatialFrame | null = null;
  private latest: SpatialFrame | null = null;
  private shownAtMs = Number.NEGATIVE_INFINITY;
  private readonly listeners = new Set<() => void>();

  /** The frame the panels show, or null; stable between changes. */
  readonly get = (): SpatialFrame | null => this.frame;

  /** Play's own frame (the 3D view's), ahead of get() by less than PANEL_INTERVAL_MS; null with it. */
  current(): SpatialFrame | null {
    return this.latest;
  }

  /** Shows a frame at once (null hands the view back to the state) and tells the subscribers. */
  set(frame: SpatialFrame | null): void {
    this.latest = frame;
    this.shownAtMs = Number.NEGATIVE_INFINITY;
    this.show(frame);
  }

  /** Play's next frame at nowMs (ms): current at once, shown to the subscribers at most once per PANEL_INTERVAL_MS. */
  advance(frame: SpatialFrame, nowMs: number): void {
    this.latest = frame;
    if (nowMs - this.shownAtMs < PANEL_INTERVAL_MS) return;
    this.shownAtMs = nowMs;
    this.show(frame);
  }

  /** Adds a change listener; returns its removal. */
  readonly subscribe = (listener: () => void): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };

  private show(frame: SpatialFrame | null): void {
    if (frame === this.frame) return;
    this.frame = frame;
    for (const listener of [...this.listeners]) listener();
  }
}

/** The frame on screen: the playhead's while Play runs ahead of the state, else the state's own (base). */
export function useShownFrame(playhead: SpatialPlayhead, base: SpatialFrame): SpatialFrame {
  return useSyncExternalStore(playhead.subscribe, playhead.get) ?? base;
}
