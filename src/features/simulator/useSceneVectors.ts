import { useMemo } from 'react';
import type { SceneVectors, VectorText, WorldVector } from '../../shared/linkage/motionVectors';
import { arrowScale } from '../../shared/linkage/motionVectors';
import type { AppState } from '../../shared/state/appState';
import { formatNumber } from '../../shared/format';
import type { Messages } from '../../shared/i18n/messages';
import type { FrameMotion, PointRates } from '../../shared/linkage/frameMotion';

function velocities(m: FrameMotion): Record<'A' | 'B' | 'P', WorldVector> {
  const v = (p: PointRates) => ({ x: p.vx, y: p.vy });
  return { A: v(m.A), B: v(m.B), P: v(m.P) };
}

function accelerations(m: FrameMotion): Record<'A' | 'B' | 'P', WorldVector> {
  const a = (p: PointRates) => ({ x: p.ax, y: p.ay });
  return { A: a(m.A), B: a(m.B), P: a(m.P) };
}

/**
 * The canvas's motion vectors for this frame, or null when both toggles are off. The scales follow the
 * crank pin's own speed r2 |ω2| and acceleration r2 sqrt(ω2⁴ + α2²), so they stay put while the linkage moves.
 */
export function useSceneVectors(state: AppState, motion: FrameMotion | null, t: Messages): SceneVectors | null {
  const {
    display: { showVelocity, showAcceleration },
    motion: { omega2RadPerS: w, alpha2RadPerS2: a },
  } = state;
  const r2 = state.design.linkage.r2;
  const unit = state.forces.lengthUnit;
  const velocityScale = useMemo(() => arrowScale(r2 * Math.abs(w)), [r2, w]);
  const accelerationScale = useMemo(() => arrowScale(r2 * Math.hypot(w * w, a)), [r2, w, a]);
  const text: VectorText = useMemo(
    () => ({
      symbol: { v: 'v', a: 'a' },
      // The bar's value in the app's length unit (= 5 mm/s).
      velocityBar: (v: string) => `= ${v} ${unit}/s`,
      accelerationBar: (v: string) => `= ${v} ${unit}/s²`,
      zero: t.vectorZero,
      clamped: t.vectorClamped,
      limit: t.limitPosition,
      formatValue: (x: number) => formatNumber(x, 3),
    }),
    [t, unit],
  );
  return useMemo(() => {
    if (!showVelocity && !showAcceleration) return null;
    return {
      velocity: showVelocity && motion ? velocities(motion) : null,
      acceleration: showAcceleration && motion ? accelerations(motion) : null,
      velocityScale: showVelocity ? velocityScale : null,
      accelerationScale: showAcceleration ? accelerationScale : null,
      limit: motion?.limit ?? false,
      text,
    };
  }, [showVelocity, showAcceleration, motion, velocityScale, accelerationScale, text]);
}
