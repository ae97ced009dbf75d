import { useEffect, useState } from 'react';
import type { MechanismSpec } from '../../mechanism';

/** How long the pointer rests (ms) before a drag's linkage is analysed (its cycle, traces and plots) while held. */
export const DRAG_REST_MS = 150;

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

/**
 * A pointer drag of a joint, kept in the page until it ends: each move redraws the linkage as drawn (no sweep, no app
 * state, no address bar, no history), the cycle (traces, plots, limits) follows when the pointer rests restMs ms or
 * lets go, and the end commits the moved linkage once (one undo step). `shown` is the spec to draw, `analysed` the spec
 * to sweep; both are `stored` when no drag is on.
 */
export function useJointDrag(stored: MechanismSpec, commit: (spec: MechanismSpec) => void, restMs = DRAG_REST_MS) {
  const [drag, setDrag] = useState<JointDrag | null>(null);
  useEffect(() => {
    if (!drag || drag.analysed === drag.now) return;
    const timer = setTimeout(() => setDrag((d) => nextJointDrag(d, { type: 'rest' }).drag), restMs);
    return () => clearTimeout(timer);
  }, [drag, restMs]);
  const on = (event: JointDragEvent) => {
    const next = nextJointDrag(drag, event);
    if (next.commit) commit(next.commit);
    setDrag(next.drag);
  };
  return {
    shown: drag?.now ?? stored,
    analysed: drag?.analysed ?? stored,
    dragging: drag !== null,
    /** Takes the stored linkage into a drag. */
    start: () => on({ type: 'grab', stored }),
    /** Draws the linkage `change` makes of the one drawn now (change may throw: the caller says why). */
    move: (change: (s: MechanismSpec) => MechanismSpec) => drag && on({ type: 'move', spec: change(drag.now) }),
    /** Lets go: commits the moved linkage (when it moved) and ends the drag. */
    end: () => on({ type: 'release' }),
  };
}
