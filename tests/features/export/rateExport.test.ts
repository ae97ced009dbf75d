import { describe, expect, it } from 'vitest';
import { frameMotion } from '../../../src/shared/linkage/frameMotion';
import { localPose } from '../../../src/shared/linkage/localPose';
import type { ShownFrame } from '../../../src/shared/linkage/shownFrame';
import { rateExport } from '../../../src/features/export/exporters';
import { degToRad } from '../../../src/solver/angles';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import type { AppState } from '../../../src/shared/state/appState';
import { effectiveInputMotion } from '../../../src/shared/state/inputMotion';
import { messagesEn } from '../../../src/shared/i18n/messagesEn';
import type { PointResponse } from '../../../src/shared/jobs/protocol';
import { referenceMotion } from '../../oracle/rates';

/** The frame an export reads: this state's pose at its θ2, with its motion (scene not needed by rate exports). */
function frameOf(state: AppState): ShownFrame {
  const local = localPose(state.linkage, state.theta2Deg, state.branch, state.coupler, false);
  const motion = frameMotion(local, effectiveInputMotion(state.omega2RadPerS, state.alpha2RadPerS2, state.direction));
  const marker = { theta2Rad: degToRad(state.theta2Deg) } as PointResponse;
  return { state, marker, motion, scene: null as unknown as ShownFrame['scene'] };
}

describe('rateExport', () => {
  for (const direction of [1, -1] as const) {
    it(`solves ω3, ω4 and α3, α4 as the oracle gives them, for ${direction === 1 ? 'counter-' : ''}clockwise input`, () => {
      const state: AppState = { ...DEFAULT_STATE, direction, omega2RadPerS: 3, alpha2RadPerS2: -2, showGhost: false };
      const input = effectiveInputMotion(state.omega2RadPerS, state.alpha2RadPerS2, direction);
      const sigma = state.branch === 'open' ? 1 : -1;
      for (const subject of ['omega', 'alpha'] as const) {
        const { inputs, marker } = rateExport(subject, frameOf(state), messagesEn);
        expect(inputs.title).toBe(subject === 'omega' ? 'ω3 and ω4 against θ2' : 'α3 and α4 against θ2');
        const { theta2Deg, series } = inputs.data;
        expect(series.map((s) => s.label)).toEqual(subject === 'omega' ? ['ω3', 'ω4'] : ['α3', 'α4']);
        expect(theta2Deg.length).toBeGreaterThan(600);
        let checked = 0;
        for (let i = 0; i < theta2Deg.length; i += 37) {
          const ref = referenceMotion(state.linkage, degToRad(theta2Deg[i]), sigma, input);
          const want = subject === 'omega' ? [ref.omega3, ref.omega4] : [ref.alpha3, ref.alpha4];
          series.forEach((s, k) => expect(s.values[i]).toBeCloseTo(want[k], 8));
          checked++;
        }
        expect(checked).toBeGreaterThan(15);
        const at = referenceMotion(state.linkage, degToRad(state.theta2Deg), sigma, input);
        expect(marker.theta2Deg).toBeCloseTo(state.theta2Deg, 12);
        const wantAt = subject === 'omega' ? [at.omega3, at.omega4] : [at.alpha3, at.alpha4];
        marker.values.forEach((v, k) => expect(v).toBeCloseTo(wantAt[k], 8));
      }
    });
  }

  it('draws the other branch faint when the ghost shows', () => {
    const { inputs } = rateExport('omega', frameOf({ ...DEFAULT_STATE, showGhost: true }), messagesEn);
    expect(inputs.data.series.map((s) => s.faint === true)).toEqual([true, false, true, false]);
  });
});
