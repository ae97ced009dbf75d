import { useMemo } from 'react';
import type { SceneVectors } from '../../shared/linkage/motionVectors';
import type { AppState } from '../../shared/state/appState';
import type { Messages } from '../../shared/i18n/messages';
import type { FrameMotion } from '../../shared/linkage/frameMotion';
import { sceneVectors, vectorScales, vectorText } from './sceneVectors';

/**
 * The canvas's motion vectors for this frame, or null when both toggles are off. The scales follow the
 * crank pin's own speed and acceleration (vectorScales), so they stay put while the linkage moves.
 */
export function useSceneVectors(state: AppState, motion: FrameMotion | null, t: Messages): SceneVectors | null {
  const {
    display: { showVelocity, showAcceleration },
    motion: { omega2RadPerS: w, alpha2RadPerS2: a },
  } = state;
  const r2 = state.design.linkage.r2;
  const unit = state.design.lengthUnit;
  const scales = useMemo(() => vectorScales(r2, w, a), [r2, w, a]);
  const text = useMemo(() => vectorText(t, unit), [t, unit]);
  return useMemo(
    () => sceneVectors({ showVelocity, showAcceleration }, scales, motion, text),
    [showVelocity, showAcceleration, scales, motion, text],
  );
}
