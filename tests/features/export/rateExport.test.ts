import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { frameMotion } from '../../../src/shared/linkage/frameMotion';
import { localPose } from '../../../src/shared/linkage/localPose';
import type { ShownFrame } from '../../../src/shared/linkage/shownFrame';
import { plotExport, rateExport } from '../../../src/features/export/exporters';
import { exportChart } from '../../../src/shared/charts/exportChart';
import { convergenceInputs } from '../../../src/shared/charts/chartInputs';
import { installFakeSvgDom } from '../../shared/charts/fakeSvgDom';
import { degToRad } from '../../../src/solver/angles';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import type { AppState } from '../../../src/shared/state/appState';
import { effectiveInputMotion } from '../../../src/shared/state/inputMotion';
import { messagesEn } from '../../../src/shared/i18n/messagesEn';
import type { PointResponse } from '../../../src/shared/solution';
import { referenceMotion } from '../../oracle/rates';
import { withFields } from '../../shared/state/stateFixtures';

/** The frame an export reads: this state's pose at its θ2, with its motion (scene not needed by rate exports). */
function frameOf(state: AppState): ShownFrame {
  const local = localPose(
    state.design.linkage,
    state.motion.theta2Deg,
    state.design.branch,
    state.design.coupler,
    false,
  );
  const motion = frameMotion(
    local,
    effectiveInputMotion(state.motion.omega2RadPerS, state.motion.alpha2RadPerS2, state.motion.direction),
  );
  const marker = { theta2Rad: degToRad(state.motion.theta2Deg) } as PointResponse;
  return { state, marker, motion, scene: null as unknown as ShownFrame['scene'] };
}

describe('rateExport', () => {
  for (const direction of [1, -1] as const) {
    it(`solves ω3, ω4 and α3, α4 as the oracle gives them, for ${direction === 1 ? 'counter-' : ''}clockwise input`, () => {
      const state: AppState = withFields(DEFAULT_STATE, {
        direction,
        omega2RadPerS: 3,
        alpha2RadPerS2: -2,
        showGhost: false,
      });
      const input = effectiveInputMotion(state.motion.omega2RadPerS, state.motion.alpha2RadPerS2, direction);
      const sigma = state.design.branch === 'open' ? 1 : -1;
      for (const subject of ['omega', 'alpha'] as const) {
        const { inputs, marker } = rateExport(subject, frameOf(state), messagesEn);
        expect(inputs.title).toBe(subject === 'omega' ? 'ω3 and ω4 against θ2' : 'α3 and α4 against θ2');
        const { theta2Deg, series } = inputs.data;
        expect(series.map((s) => s.label)).toEqual(subject === 'omega' ? ['ω3', 'ω4'] : ['α3', 'α4']);
        expect(theta2Deg.length).toBeGreaterThan(600);
        let checked = 0;
        for (let i = 0; i < theta2Deg.length; i += 37) {
          const ref = referenceMotion(state.design.linkage, degToRad(theta2Deg[i]), sigma, input);
          const want = subject === 'omega' ? [ref.omega3, ref.omega4] : [ref.alpha3, ref.alpha4];
          series.forEach((s, k) => expect(s.values[i]).toBeCloseTo(want[k], 8));
          checked++;
        }
        expect(checked).toBeGreaterThan(15);
        const at = referenceMotion(state.design.linkage, degToRad(state.motion.theta2Deg), sigma, input);
        expect(marker.theta2Deg).toBeCloseTo(state.motion.theta2Deg, 12);
        const wantAt = subject === 'omega' ? [at.omega3, at.omega4] : [at.alpha3, at.alpha4];
        marker.values.forEach((v, k) => expect(v).toBeCloseTo(wantAt[k], 8));
      }
    });
  }

  it('draws the other branch faint when the ghost shows', () => {
    const { inputs } = rateExport('omega', frameOf(withFields(DEFAULT_STATE, { showGhost: true })), messagesEn);
    expect(inputs.data.series.map((s) => s.faint === true)).toEqual([true, false, true, false]);
  });
});

describe('plotExport', () => {
  let uninstall = () => {};
  beforeAll(() => {
    uninstall = installFakeSvgDom();
  });
  afterAll(() => uninstall());
  const state: AppState = withFields(DEFAULT_STATE, { omega2RadPerS: 3, showGhost: false });
  const context = { frame: frameOf(state), point: null, deg: null, t: messagesEn, canvasSize: { width: 0, height: 0 } };

  it('exports ω3 and ω4 at 640 x 360 with its title and the marker at θ2 on both curves', () => {
    const chart = plotExport('omega', context);
    expect([chart.width, chart.height]).toEqual([640, 360]);
    const svg = exportChart(chart, 'svg');
    expect(svg).toContain('>ω3 and ω4 against θ2</text>');
    expect(svg).toContain('>θ2 (°)</text>');
    // Plot 640 - 50 - 14 = 576 px wide for 360 degrees.
    const x1 = Number(/<line class="mline"[^>]* x1="([^"]+)"/.exec(svg)?.[1]);
    expect(x1).toBeCloseTo((state.motion.theta2Deg * 576) / 360, 9);
    const dots = [...svg.matchAll(/<circle [^>]*cx="([^"]+)"/g)].map((m) => Number(m[1]));
    expect(dots).toHaveLength(2);
    dots.forEach((cx) => expect(cx).toBeCloseTo(x1, 9));
  });

  it('exports the convergence chart at its own size, with its title', () => {
    const chart = plotExport('convergence', context);
    expect([chart.width, chart.height]).toEqual([560, 340]);
    expect(exportChart(chart, 'svg')).toContain(
      `>${convergenceInputs(null, state.solver.nrStart, messagesEn).title}</text>`,
    );
  });
});
