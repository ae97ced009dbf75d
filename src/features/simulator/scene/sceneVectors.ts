import type { ArrowScale, SceneVectors, VectorText, WorldVector } from '../../../shared/linkage/motionVectors';
import { arrowScale } from '../../../shared/linkage/motionVectors';
import type { AppState } from '../../../shared/state/appState';
import type { LengthUnit } from '../../../shared/state/slices/designSlice';
import { formatNumber } from '../../../shared/format';
import type { Messages } from '../../../shared/i18n/messages';
import type { FrameMotion, PointRates } from '../../../shared/linkage/frameMotion';

function velocities(m: FrameMotion): Record<'A' | 'B' | 'P', WorldVector> {
  const v = (p: PointRates) => ({ x: p.vx, y: p.vy });
  return { A: v(m.A), B: v(m.B), P: v(m.P) };
}

function accelerations(m: FrameMotion): Record<'A' | 'B' | 'P', WorldVector> {
  const a = (p: PointRates) => ({ x: p.ax, y: p.ay });
  return { A: a(m.A), B: a(m.B), P: a(m.P) };
}

/** The arrows' texts in the page's language, with the app's length unit (the bar reads "= 5 mm/s"). */
export function vectorText(t: Messages, unit: LengthUnit): VectorText {
  return {
    symbol: { v: 'v', a: 'a' },
    velocityBar: (v: string) => `= ${v} ${unit}/s`,
    accelerationBar: (v: string) => `= ${v} ${unit}/s²`,
    zero: t.vectorZero,
    clamped: t.vectorClamped,
    limit: t.limitPosition,
    formatValue: (x: number) => formatNumber(x, 3),
  };
}

/** The arrows' scales (null where none reads). */
export interface VectorScales {
  velocity: ArrowScale | null;
  acceleration: ArrowScale | null;
}

/** The arrows' scales: from the crank pin's own speed r2 |ω2| and acceleration r2 sqrt(ω2⁴ + α2²). */
export function vectorScales(r2: number, w: number, a: number): VectorScales {
  return { velocity: arrowScale(r2 * Math.abs(w)), acceleration: arrowScale(r2 * Math.hypot(w * w, a)) };
}

/**
 * The canvas's motion vectors for a frame, or null when both toggles are off. Pure: the scene builder builds
 * them for every frame, the page's canvas and the live stage's worker alike (sceneBuilder.ts).
 */
export function sceneVectors(
  display: Pick<AppState['display'], 'showVelocity' | 'showAcceleration'>,
  scales: VectorScales,
  motion: FrameMotion | null,
  text: VectorText,
): SceneVectors | null {
  const { showVelocity, showAcceleration } = display;
  if (!showVelocity && !showAcceleration) return null;
  return {
    velocity: showVelocity && motion ? velocities(motion) : null,
    acceleration: showAcceleration && motion ? accelerations(motion) : null,
    velocityScale: showVelocity ? scales.velocity : null,
    accelerationScale: showAcceleration ? scales.acceleration : null,
    limit: motion?.limit ?? false,
    text,
  };
}
