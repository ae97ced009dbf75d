import { useMemo } from 'react';
import { degToRad } from '../../solver';
import type { SpatialState } from '../../shared/state/appState';
import type { OutputMotion, SpatialClassification, SpatialModel, SpatialPose, SpatialSweep } from '../../spatial';
import {
  classifyRSSR,
  classifySpherical,
  outputMotion,
  solveRSSR,
  solveSpherical,
  sweepSpatial,
  transmissionAngle,
} from '../../spatial';
import type { SceneLinkage } from './sceneData';
import { sceneLinkage } from './sceneData';
import { modelOf } from './spatialModel';

/** Steps per turn of the plots' and the 3D view's sweep (half a degree). */
export const SWEEP_STEPS = 720;

/** The input motion the page's rates are for (the state's ω2 and α2, as the numerics take them). */
export interface SpatialInput {
  omega2: number;
  alpha2: number;
}

/** The state's input motion. */
export function inputOf(s: Pick<SpatialState, 'omega2RadPerS' | 'alpha2RadPerS2'>): SpatialInput {
  return { omega2: s.omega2RadPerS, alpha2: s.alpha2RadPerS2 };
}

/** What the page shows of one linkage (changes only when the linkage or branch does). */
export interface SpatialAnalysis {
  model: SpatialModel;
  input: SpatialInput;
  sweep: SpatialSweep;
  classification: SpatialClassification;
  motion: OutputMotion;
  scene: SceneLinkage;
}

/** The linkage's analysis, or the error that names a bad value (null analysis). */
export function analyse(s: SpatialState): { analysis: SpatialAnalysis | null; error: string | null } {
  try {
    const model = modelOf(s);
    const input = inputOf(s);
    const sweep = sweepSpatial(model, s.branch, { steps: SWEEP_STEPS, ...input });
    const classification = model.kind === 'spherical' ? classifySpherical(model.linkage) : classifyRSSR(model.linkage);
    const motion = outputMotion(model, s.branch);
    return {
      analysis: { model, input, sweep, classification, motion, scene: sceneLinkage(model, sweep) },
      error: null,
    };
  } catch (e) {
    return { analysis: null, error: e instanceof Error ? e.message : String(e) };
  }
}

/** The pose at θ2 with the input motion, or null where the loop cannot close. */
export function poseAt(
  model: SpatialModel,
  theta2Deg: number,
  branch: SpatialState['branch'],
  input: SpatialInput,
): SpatialPose | null {
  const t2 = degToRad(theta2Deg);
  return model.kind === 'spherical'
    ? solveSpherical(model.linkage, t2, branch, input)
    : solveRSSR(model.linkage, t2, branch, input);
}

/** The transmission angle at θ2 (radians) or null. */
export function muAt(model: SpatialModel, theta2Deg: number, branch: SpatialState['branch']): number | null {
  return transmissionAngle(model, degToRad(theta2Deg), branch);
}

/** The analysis of the state's linkage, recomputed when a linkage value, the branch or the input motion changes (not θ2). */
export function useSpatialAnalysis(s: SpatialState): { analysis: SpatialAnalysis | null; error: string | null } {
  const { kind, a1Deg, a2Deg, a3Deg, a4Deg, pDistDeg, pAngleDeg, r2, r3, r4, a, h2, h4, betaDeg, branch } = s;
  const { omega2RadPerS, alpha2RadPerS2 } = s;
  return useMemo(
    () =>
      analyse({
        kind,
        a1Deg,
        a2Deg,
        a3Deg,
        a4Deg,
        pDistDeg,
        pAngleDeg,
        r2,
        r3,
        r4,
        a,
        h2,
        h4,
        betaDeg,
        branch,
        theta2Deg: 0,
        omega2RadPerS,
        alpha2RadPerS2,
      }),
    [
      kind,
      a1Deg,
      a2Deg,
      a3Deg,
      a4Deg,
      pDistDeg,
      pAngleDeg,
      r2,
      r3,
      r4,
      a,
      h2,
      h4,
      betaDeg,
      branch,
      omega2RadPerS,
      alpha2RadPerS2,
    ],
  );
}
