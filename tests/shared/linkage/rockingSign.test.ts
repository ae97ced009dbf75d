import { describe, expect, it } from 'vitest';
import { frameMotion } from '../../../src/shared/linkage/frameMotion';
import { localPose } from '../../../src/shared/linkage/localPose';
import { plotRates } from '../../../src/shared/charts/rateInputs';
import { classify } from '../../../src/solver/classify';
import type { Branch } from '../../../src/solver/types';
import { advanceTheta2, rangeToDeg } from '../../../src/shared/state/animation';
import type { Direction } from '../../../src/shared/state/appState';
import { effectiveInputMotion } from '../../../src/shared/state/inputMotion';
import type { PlotSeries } from '../../../src/shared/solution';
import { referenceAngles } from '../../oracle/reference';

/** A triple rocker: the input rocks between two limits (the e2e export case). */
const L = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
const OMEGA = 10;

interface Frame {
  theta2Deg: number;
  direction: Direction;
  branch: Branch;
}

describe('the rocking input reverses ω2 in step with the animation', () => {
  const range = rangeToDeg(classify(L).inputRange);
  const iv = range.intervals[0];
  // Frames of the animation across the upper limit: it reverses and switches branch there.
  const frames: Frame[] = [{ theta2Deg: iv.hi - 1, direction: 1, branch: 'open' }];
  for (let k = 0; k < 40; k++) {
    const f = frames[frames.length - 1];
    frames.push(advanceTheta2(f.theta2Deg, 0.05, f.direction, f.branch, range));
  }

  it('passes the limit: the direction flips within the frames', () => {
    expect(frames.some((f) => f.direction === -1)).toBe(true);
  });

  it('gives ω4 the sign of the rocker motion the oracle sees from frame to frame', () => {
    let checked = 0;
    for (let k = 1; k < frames.length - 1; k++) {
      const f = frames[k];
      const m = frameMotion(
        localPose(L, f.theta2Deg, f.branch, { distance: 0, angleDeg: 0 }, false),
        effectiveInputMotion(OMEGA, 0, f.direction),
      );
      if (!m || !Number.isFinite(m.rates.omega4)) continue;
      const t4 = (g: Frame) => {
        const p = referenceAngles(L, (g.theta2Deg * Math.PI) / 180, g.branch === 'open' ? 1 : -1);
        if (!p) throw new Error(`oracle: no pose at ${g.theta2Deg}`);
        return p.theta4;
      };
      // The rocker's motion across this frame, by the 60-digit positions of its neighbours (time runs forward).
      const d = t4(frames[k + 1]) - t4(frames[k - 1]);
      if (Math.abs(d) < 1e-6) continue;
      expect(Math.sign(m.rates.omega4), `frame ${k} at ${f.theta2Deg} ${f.branch} dir ${f.direction}`).toBe(
        Math.sign(d),
      );
      checked++;
    }
    expect(checked).toBeGreaterThan(30);
  });
});

describe('plotRates', () => {
  const rates = {
    omega3: Float64Array.of(1, -2),
    omega4: Float64Array.of(3, Number.NaN),
    alpha3: Float64Array.of(5, 6),
    alpha4: Float64Array.of(-7, 8),
  };
  const plot: PlotSeries = {
    theta2Deg: Float64Array.of(0, 1),
    open: { theta3: rates.omega3, theta4: rates.omega3, rates },
    crossed: null,
  };

  it('keeps the rates as solved for the counter-clockwise direction', () => {
    expect(plotRates(plot, 1)?.open).toBe(rates);
  });
  it('flips ω3 and ω4 and keeps α3 and α4 for the clockwise direction (α is even in ω2)', () => {
    const r = plotRates(plot, -1)?.open;
    expect([...r!.omega3]).toEqual([-1, 2]);
    expect([...r!.omega4]).toEqual([-3, Number.NaN]);
    expect(r!.alpha3).toBe(rates.alpha3);
    expect(r!.alpha4).toBe(rates.alpha4);
  });
  it('is null without plot rates', () => {
    expect(plotRates(null, 1)).toBeNull();
    expect(plotRates({ ...plot, open: { theta3: plot.theta2Deg, theta4: plot.theta2Deg } }, 1)).toBeNull();
  });
});
