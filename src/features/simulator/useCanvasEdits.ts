import { useCallback } from 'react';
import type { Dispatch } from 'react';
import type { Action, CouplerPoint } from '../../shared/state/appState';

/** Handlers for what the canvas edits directly: theta2 (dragging A, arrow keys) and the coupler point (dragging P). */
export interface CanvasEdits {
  onTheta2: (theta2Deg: number) => void;
  onCoupler: (coupler: CouplerPoint) => void;
}

/**
 * Stable canvas edit handlers. Taking hold of the crank stops Play, so the hand and the animation do not
 * fight over theta2.
 */
export function useCanvasEdits(dispatch: Dispatch<Action>): CanvasEdits {
  const onTheta2 = useCallback(
    (deg: number) => {
      dispatch({ type: 'setPlaying', playing: false });
      dispatch({ type: 'setTheta2', deg });
    },
    [dispatch],
  );
  const onCoupler = useCallback((coupler: CouplerPoint) => dispatch({ type: 'setCoupler', coupler }), [dispatch]);
  return { onTheta2, onCoupler };
}
