// The closed form itself, not the solver's barrel: the barrel would pull the sweep and NR into the main bundle.
import { TWO_PI } from '../../solver/angles';
import { solveClosedForm } from '../../solver/closedForm';
import type { Branch } from '../../solver/types';
import { formatNumber } from '../../shared/format';
import type { ForceLayer, ForceText, SceneForces } from '../../shared/linkage/forceVectors';
import type { LocalPose } from '../../shared/linkage/localPose';
import { arrowScale } from '../../shared/linkage/motionVectors';
import type { AppState, Locale } from '../../shared/state/appState';
import type { ForceSetup } from './forceModel';
import { forceSetup, poseForces } from './forceModel';
import { forcesMessages } from './forcesMessages';

/** Poses per turn the arrows' scale is taken over (cheap: a closed-form pose and the forces, well under a ms). */
const SCALE_SAMPLES = 72;

/**
 * A typical pin-force magnitude over a turn (N): the 90th percentile of |F12|, |F32|, |F43| and |F14| at
 * SCALE_SAMPLES poses (a few samples near a toggle run away; the arrows keep a scale that reads). NaN without any.
 */
export function typicalPinForce(setup: ForceSetup, branch: Branch): number {
  const mags: number[] = [];
  for (let i = 0; i < SCALE_SAMPLES; i++) {
    const theta2 = (TWO_PI * i) / SCALE_SAMPLES;
    const a = solveClosedForm(setup.linkage, theta2, branch);
    if (!a) continue;
    const p = poseForces(setup, theta2, { theta3: a.theta3, theta4: a.theta4 });
    if (!p.forces) continue;
    const { F12, F32, F43, F14 } = p.forces;
    for (const f of [F12, F32, F43, F14]) mags.push(Math.hypot(f.x, f.y));
  }
  if (mags.length === 0) return Number.NaN;
  mags.sort((x, y) => x - y);
  return mags[Math.min(mags.length - 1, Math.floor(0.9 * mags.length))];
}

/** The overlay's texts in a language. */
function forceText(locale: Locale): ForceText {
  const t = forcesMessages.get(locale);
  return {
    label: { O2: 'F12', A: 'F32', B: 'F43', O4: 'F14' },
    bar: t.vectorBar,
    zero: t.vectorZero,
    clamped: t.vectorClamped,
    limit: t.vectorLimit,
    // The scale's value is 1, 2 or 5 times a power of ten: all its digits (1000, not 1e+3).
    formatValue: (x) => formatNumber(x, 6),
  };
}

/** What the setup and the scale were made from: they are rebuilt only when one of these changes (not every frame). */
interface LayerInputs {
  linkage: AppState['design']['linkage'];
  coupler: AppState['design']['coupler'];
  branch: AppState['design']['branch'];
  forces: AppState['forces'];
  omega: number;
  alpha: number;
  direction: number;
}

function sameInputs(a: LayerInputs, b: LayerInputs): boolean {
  return (
    a.linkage === b.linkage &&
    a.coupler === b.coupler &&
    a.branch === b.branch &&
    a.forces === b.forces &&
    a.omega === b.omega &&
    a.alpha === b.alpha &&
    a.direction === b.direction
  );
}

/**
 * A force layer for the canvas (shared/linkage ForceLayer): for the frame on screen, the pin forces F12 at O2, F32
 * at A, F43 at B and F14 at O4 (SI, from the state's unit and mass model) with a scale that stays put while the
 * linkage moves; null (and nothing solved) unless Forces and its arrows are on. It keeps the last setup, scale and
 * texts, so a frame of Play solves only the one pose.
 */
export function createForceLayer(): ForceLayer {
  let inputs: LayerInputs | null = null;
  let setup: ForceSetup | null = null;
  let scale: SceneForces['scale'] = null;
  let texts: { locale: Locale; text: ForceText } | null = null;
  return (state: AppState, local: LocalPose): SceneForces | null => {
    const f = state.forces;
    if (!f.enabled || !f.showVectors) return null;
    // Not the design object itself: each frame of Play carries a new one (the branch it is on).
    const next: LayerInputs = {
      linkage: state.design.linkage,
      coupler: state.design.coupler,
      branch: state.design.branch,
      forces: f,
      omega: state.motion.omega2RadPerS,
      alpha: state.motion.alpha2RadPerS2,
      direction: state.motion.direction,
    };
    if (!inputs || !setup || !sameInputs(inputs, next)) {
      inputs = next;
      setup = forceSetup(state);
      scale = arrowScale(typicalPinForce(setup, state.design.branch));
    }
    if (!texts || texts.locale !== state.shell.locale) {
      texts = { locale: state.shell.locale, text: forceText(state.shell.locale) };
    }
    const p = poseForces(setup, local.theta2Rad, local.pose);
    const pins = p.forces ? { O2: p.forces.F12, A: p.forces.F32, B: p.forces.F43, O4: p.forces.F14 } : null;
    return { pins, scale, limit: p.status === 'limit-position', text: texts.text };
  };
}
