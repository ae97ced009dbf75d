import { useEffect, useRef, useState } from 'react';
import type { MechanismSpec } from '../../mechanism';
import type { LiveSource } from './livePlayhead';
import { createLiveSource } from './livePlayhead';

/** How long the pointer rests (ms) before a drag's linkage is analysed (its cycle, traces and plots) while held. */
export const DRAG_REST_MS = 250;

/** How many of the latest gaps between moves restDelayMs looks at. */
const GAPS_KEPT = 5;

/**
 * How long (ms) the pointer must rest before the drag's linkage is swept: restMs, or twice the median of the latest
 * gaps between moves (ms) when that is longer, so a drag on a slow or busy machine (moves far apart) is not swept
 * between every two moves. Throws for a restMs that is not a positive finite number.
 */
export function restDelayMs(gapsMs: readonly number[], restMs: number): number {
  if (!(restMs > 0 && Number.isFinite(restMs)))
    throw new Error(`restMs must be a positive finite number, got ${restMs}`);
  const latest = gapsMs
    .slice(-GAPS_KEPT)
    .filter((g) => Number.isFinite(g) && g >= 0)
    .sort((a, b) => a - b);
  if (latest.length === 0) return restMs;
  const mid = latest.length >> 1;
  const median = latest.length % 2 ? latest[mid] : (latest[mid - 1] + latest[mid]) / 2;
  return Math.max(restMs, 2 * median);
}

/** A drag in progress: the spec at the grab, the spec drawn now, and the spec last analysed (swept). */
export interface JointDrag {
  from: MechanismSpec;
  now: MechanismSpec;
  analysed: MechanismSpec;
}

/** What happens to a drag: a grab of the stored spec, a move to a new spec, the pointer at rest, the pointer let go. */
export type JointDragEvent =
  | { type: 'grab'; stored: MechanismSpec }
  | { type: 'move'; spec: MechanismSpec }
  | { type: 'rest' }
  | { type: 'release' };

/**
 * The next drag after an event (null: no drag), and the spec to commit to the app when the event ends a drag that moved
 * something (else null). A move draws a new spec without analysing it; a rest analyses the one drawn.
 */
export function nextJointDrag(
  drag: JointDrag | null,
  event: JointDragEvent,
): { drag: JointDrag | null; commit: MechanismSpec | null } {
  switch (event.type) {
    case 'grab':
      return { drag: { from: event.stored, now: event.stored, analysed: event.stored }, commit: null };
    case 'move':
      return { drag: drag && event.spec !== drag.now ? { ...drag, now: event.spec } : drag, commit: null };
    case 'rest':
      return { drag: drag && drag.analysed !== drag.now ? { ...drag, analysed: drag.now } : drag, commit: null };
    case 'release':
      return { drag: null, commit: drag && drag.now !== drag.from ? drag.now : null };
  }
}

/** The spec a drag draws now (null: no drag), read by the canvas alone. */
export type DraggedSource = LiveSource<MechanismSpec | null>;

/**
 * A pointer drag of a joint, kept in the page until it ends: each move redraws the linkage as drawn and re-renders the
 * canvas alone (the spec drawn is in `shown`, a source the canvas reads: no sweep, no page render, no app state, no
 * address bar, no history); the cycle (traces, plots, limits) follows when the pointer rests restMs ms or lets go (the
 * page re-renders with the new `analysed`); the end commits the moved linkage once (one undo step). `analysed` is
 * `stored` when no drag is on.
 */
export function useJointDrag(stored: MechanismSpec, commit: (spec: MechanismSpec) => void, restMs = DRAG_REST_MS) {
  const [drag] = useState(() => createLiveSource<JointDrag | null>(null));
  const [shown] = useState(() => createLiveSource<MechanismSpec | null>(null));
  // What the page renders from: the spec last analysed (null: no drag). It changes at a grab, a rest and a release.
  const [analysed, setAnalysed] = useState<MechanismSpec | null>(null);
  const rest = useRef<ReturnType<typeof setTimeout> | null>(null);
  // The latest gaps between moves (ms) and the last move's time: the rest's delay follows the moves' pace.
  const pace = useRef<{ last: number | null; gaps: number[] }>({ last: null, gaps: [] });
  const on = (event: JointDragEvent) => {
    const before = drag.get();
    const next = nextJointDrag(before, event);
    drag.set(next.drag);
    shown.set(next.drag?.now ?? null);
    // Only a new analysed spec re-renders the page: even a set of the same state can render it once more.
    if (next.drag?.analysed !== before?.analysed || (next.drag === null) !== (before === null))
      setAnalysed(next.drag?.analysed ?? null);
    if (next.commit) commit(next.commit);
  };
  const clearRest = () => {
    if (rest.current !== null) clearTimeout(rest.current);
    rest.current = null;
  };
  useEffect(() => clearRest, []);
  return {
    analysed: analysed ?? stored,
    dragging: analysed !== null,
    shown: shown as DraggedSource,
    /** Takes the stored linkage into a drag. */
    start: () => {
      pace.current = { last: null, gaps: [] };
      on({ type: 'grab', stored });
    },
    /** Draws the linkage `change` makes of the one drawn now (change may throw: the caller says why). */
    move: (change: (s: MechanismSpec) => MechanismSpec) => {
      const d = drag.get();
      if (!d) return;
      on({ type: 'move', spec: change(d.now) });
      const now = performance.now();
      const p = pace.current;
      if (p.last !== null) p.gaps = [...p.gaps.slice(1 - GAPS_KEPT), now - p.last];
      p.last = now;
      clearRest();
      rest.current = setTimeout(() => on({ type: 'rest' }), restDelayMs(p.gaps, restMs));
    },
    /** Lets go: commits the moved linkage (when it moved) and ends the drag. */
    end: () => {
      clearRest();
      on({ type: 'release' });
    },
  };
}
