import { withFields } from './stateFixtures';
import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE, reducer } from '../../../src/shared/state/appState';

describe('reducer', () => {
  it('starts from the report linkage at 45 degrees on the open branch', () => {
    expect(DEFAULT_STATE.design.linkage).toEqual({ r1: 6, r2: 2, r3: 5, r4: 5 });
    expect(DEFAULT_STATE.motion.theta2Deg).toBe(45);
    expect(DEFAULT_STATE.design.branch).toBe('open');
    expect(DEFAULT_STATE.design.coupler).toEqual({ distance: 2.5, angleDeg: 30 });
  });
  it('sets one length and keeps the others', () => {
    const s = reducer(DEFAULT_STATE, { type: 'setLength', field: 'r2', value: 2.5 });
    expect(s.design.linkage).toEqual({ r1: 6, r2: 2.5, r3: 5, r4: 5 });
    expect(DEFAULT_STATE.design.linkage.r2).toBe(2);
  });
  it('returns the same object when nothing changes', () => {
    expect(reducer(DEFAULT_STATE, { type: 'setLength', field: 'r1', value: 6 })).toBe(DEFAULT_STATE);
    expect(reducer(DEFAULT_STATE, { type: 'setTheta2', deg: 405 })).toBe(DEFAULT_STATE);
  });
  it('normalises theta2 and clamps the speed', () => {
    expect(reducer(DEFAULT_STATE, { type: 'setTheta2', deg: -90 }).motion.theta2Deg).toBe(270);
    expect(reducer(DEFAULT_STATE, { type: 'setSpeed', degPerFrame: 50 }).motion.speedDegPerFrame).toBe(10);
    expect(reducer(DEFAULT_STATE, { type: 'setSpeed', degPerFrame: 0.1 }).motion.speedDegPerFrame).toBe(0.5);
  });
  it('toggles the branch', () => {
    expect(reducer(DEFAULT_STATE, { type: 'toggleBranch' }).design.branch).toBe('crossed');
  });
  it('applies a preset and resets the view', () => {
    const zoomed = reducer(DEFAULT_STATE, { type: 'setView', view: { zoom: 3, panX: 0.2, panY: 0 } });
    const s = reducer(zoomed, {
      type: 'applyPreset',
      linkage: { r1: 4, r2: 2, r3: 4, r4: 2 },
      theta2Deg: 45,
      branch: 'open',
      coupler: { distance: 2, angleDeg: 45 },
    });
    expect(s.design.linkage).toEqual({ r1: 4, r2: 2, r3: 4, r4: 2 });
    expect(s.display.view).toEqual({ zoom: 1, panX: 0, panY: 0 });
  });
  it('animates theta2, direction and branch together', () => {
    const s = reducer(DEFAULT_STATE, { type: 'animate', theta2Deg: 370, direction: -1, branch: 'crossed' });
    expect(s).toEqual(withFields(DEFAULT_STATE, { theta2Deg: 10, direction: -1, branch: 'crossed' }));
  });
  it('starts the rates at 10 rad/s and 0 rad/s², and the transmission band at 40° to 140°', () => {
    expect(DEFAULT_STATE.motion).toMatchObject({ omega2RadPerS: 10, alpha2RadPerS2: 0 });
    expect(DEFAULT_STATE.display).toMatchObject({ muBandLoDeg: 40, muBandHiDeg: 140 });
  });
  it('sets the input motion, one rate at a time', () => {
    const s = reducer(DEFAULT_STATE, { type: 'setInputMotion', omega2RadPerS: -3 });
    expect([s.motion.omega2RadPerS, s.motion.alpha2RadPerS2]).toEqual([-3, 0]);
    expect(reducer(s, { type: 'setInputMotion', alpha2RadPerS2: 2 }).motion.alpha2RadPerS2).toBe(2);
    expect(reducer(DEFAULT_STATE, { type: 'setInputMotion', omega2RadPerS: 10 })).toBe(DEFAULT_STATE);
  });
  it('sets the transmission band and refuses one whose edges cross', () => {
    expect(reducer(DEFAULT_STATE, { type: 'setMuBand', loDeg: 30, hiDeg: 150 }).display).toMatchObject({
      muBandLoDeg: 30,
      muBandHiDeg: 150,
    });
    expect(reducer(DEFAULT_STATE, { type: 'setMuBand', loDeg: 90, hiDeg: 90 })).toBe(DEFAULT_STATE);
    expect(reducer(DEFAULT_STATE, { type: 'setMuBand', loDeg: 100, hiDeg: 60 })).toBe(DEFAULT_STATE);
  });
  it('rounds and clamps the sample count', () => {
    expect(reducer(DEFAULT_STATE, { type: 'setSamples', samples: 3600.4 }).solver.samples).toBe(3600);
    expect(reducer(DEFAULT_STATE, { type: 'setSamples', samples: 1 }).solver.samples).toBe(12);
  });
  it('keeps every slice a change does not touch as the same object (memoised views stay put)', () => {
    const s = reducer(DEFAULT_STATE, { type: 'setTheta2', deg: 90 });
    expect(s.motion).not.toBe(DEFAULT_STATE.motion);
    for (const k of ['design', 'display', 'solver', 'shell', 'lab'] as const) expect(s[k], k).toBe(DEFAULT_STATE[k]);
  });
  it('stops Play when the page changes, and only then', () => {
    const playing = reducer(DEFAULT_STATE, { type: 'setPlaying', playing: true });
    expect(reducer(playing, { type: 'setPage', page: 'simulator' })).toBe(playing);
    const lab = reducer(playing, { type: 'setPage', page: 'lab' });
    expect([lab.shell.page, lab.motion.playing]).toEqual(['lab', false]);
  });
  it('applies a preset across the design, the input angle and the view, and nothing else', () => {
    const moved = withFields(DEFAULT_STATE, { view: { zoom: 2, panX: 0.1, panY: 0 }, showGrid: false, samples: 720 });
    const s = reducer(moved, {
      type: 'applyPreset',
      linkage: { r1: 4, r2: 1, r3: 4, r4: 3 },
      theta2Deg: -10,
      branch: 'crossed',
      coupler: { distance: 1, angleDeg: 0 },
    });
    expect(s).toEqual(
      withFields(moved, {
        linkage: { r1: 4, r2: 1, r3: 4, r4: 3 },
        theta2Deg: 350,
        branch: 'crossed',
        coupler: { distance: 1, angleDeg: 0 },
        view: { zoom: 1, panX: 0, panY: 0 },
      }),
    );
  });
});
