import { describe, expect, it } from 'vitest';
import { PLAY_DEG_PER_S, playStep } from '../../../src/features/spatial/spatialPlay';
import type { SpatialModel } from '../../../src/spatial';
import { closer, sphericalOracle } from '../../spatial/oracle';

const rad = (deg: number) => (deg * Math.PI) / 180;
const input = { omega2: 1, alpha2: 0 };
/** A spherical crank-rocker (the page's first preset's arcs): its input turns fully. */
const crank: SpatialModel = { kind: 'spherical', linkage: { a1: rad(60), a2: rad(20), a3: rad(55), a4: rad(45) } };
/** Arcs whose input rocks: the loop opens for part of the turn (checked with the oracle below). */
const rockerArcs = { a1: rad(40), a2: rad(70), a3: rad(35), a4: rad(60) };
const rocker: SpatialModel = { kind: 'spherical', linkage: rockerArcs };

describe('playStep', () => {
  it('moves θ2 by PLAY_DEG_PER_S × dt in its direction, to the oracle’s pose, on the same branch', () => {
    const step = playStep(crank, input, { theta2Deg: 30, branch: 'open', direction: 1 }, 0.02);
    expect(step.turned).toBe(false);
    expect(step.theta2Deg).toBeCloseTo(30 + PLAY_DEG_PER_S * 0.02, 12);
    const o = sphericalOracle({ a1: rad(60), a2: rad(20), a3: rad(55), a4: rad(45) }, rad(step.theta2Deg), 'open')!;
    // The solver's closed form against the 50-digit oracle: rounding only (well-conditioned pose).
    expect(step.pose!.B.x).toBeCloseTo(o.B.x, 10);
    expect(step.pose!.B.y).toBeCloseTo(o.B.y, 10);
    const back = playStep(crank, input, { theta2Deg: 1, branch: 'crossed', direction: -1 }, 0.1);
    expect(back.theta2Deg).toBeCloseTo(360 - 8, 10); // wraps to [0, 360)
    expect(back.branch).toBe('crossed');
  });

  it('turns back on the other branch at a limit of the input, where the oracle says the loop opens', () => {
    const closes = closer('spherical', rockerArcs);
    // The first whole degree up from a closing θ2 where the loop no longer closes (the oracle's scan, 0.5° steps).
    let lastClosed = -1;
    for (let t = 0; t < 720; t++) {
      const deg = t / 2;
      if (closes(rad(deg))) lastClosed = deg;
      else if (lastClosed >= 0) break;
    }
    expect(lastClosed).toBeGreaterThanOrEqual(0);
    const dt = 0.5 / PLAY_DEG_PER_S;
    const turn = playStep(rocker, input, { theta2Deg: lastClosed, branch: 'open', direction: 1 }, dt);
    expect(turn).toMatchObject({ turned: true, theta2Deg: lastClosed, branch: 'crossed', direction: -1 });
    expect(turn.pose).not.toBeNull();
    const after = playStep(rocker, input, turn, dt);
    expect(after.turned).toBe(false);
    expect(after.theta2Deg).toBeCloseTo(lastClosed - 0.5, 10);
    expect(after.branch).toBe('crossed');
  });

  it('names a bad time step', () => {
    expect(() => playStep(crank, input, { theta2Deg: 0, branch: 'open', direction: 1 }, Number.NaN)).toThrow(
      /dtS.*NaN/,
    );
    expect(() => playStep(crank, input, { theta2Deg: 0, branch: 'open', direction: 1 }, -1)).toThrow(/dtS.*-1/);
  });
});
