import { describe, expect, it } from 'vitest';
import { HOLD_STEPS_PER_S, KeyHold, applyMove, keyStep, moveByRates } from '../../../src/features/spatial/keyHold';
import type { ViewMove } from '../../../src/features/spatial/viewProtocol';

const DEG = Math.PI / 180;

/** A view that adds up what it is asked to do. */
function recordingView() {
  const v = {
    azimuth: 0,
    elevation: 0,
    x: 0,
    y: 0,
    zoom: 1,
    calls: [] as string[],
    resets: 0,
    orbitBy(a: number, e: number) {
      v.azimuth += a;
      v.elevation += e;
      v.calls.push('orbit');
    },
    panBy(dx: number, dy: number) {
      v.x += dx;
      v.y += dy;
      v.calls.push('pan');
    },
    zoomBy(f: number) {
      v.zoom *= f;
      v.calls.push('zoom');
    },
    resetView() {
      v.resets++;
    },
  };
  return v;
}

describe('keyStep', () => {
  it('turns 5° by an arrow, pans a tenth of the height with shift, zooms 1.2× by + = and -, resets by 0', () => {
    expect(keyStep('ArrowRight', false)).toEqual({ op: 'orbit', dAzimuth: 5 * DEG, dElevation: 0 });
    expect(keyStep('ArrowDown', false)).toEqual({ op: 'orbit', dAzimuth: 0, dElevation: -5 * DEG });
    expect(keyStep('ArrowLeft', true)).toEqual({ op: 'pan', dx: -0.1, dy: 0 });
    expect(keyStep('ArrowUp', true)).toEqual({ op: 'pan', dx: 0, dy: 0.1 });
    expect(keyStep('+', false)).toEqual({ op: 'zoom', factor: 1.2 });
    expect(keyStep('=', false)).toEqual({ op: 'zoom', factor: 1.2 });
    expect(keyStep('-', false)).toEqual({ op: 'zoom', factor: 1 / 1.2 });
    expect(keyStep('0', false)).toEqual({ op: 'reset' });
    expect(keyStep('a', false)).toBeNull();
    expect(keyStep('Enter', true)).toBeNull();
  });
});

describe('KeyHold', () => {
  it('steps once for a press, holds from the first repeat on, and lets go on release', () => {
    const keys = new KeyHold();
    expect(keys.down('ArrowRight', 'ArrowRight', false, false)).toEqual({
      handled: true,
      step: { op: 'orbit', dAzimuth: 5 * DEG, dElevation: 0 },
      changed: false,
    });
    expect(keys.rates()).toBeNull();
    expect(keys.down('ArrowRight', 'ArrowRight', false, true)).toEqual({ handled: true, step: null, changed: true });
    // 20 steps of 5° a second: 100°/s.
    expect(keys.rates()!.dAzimuth).toBeCloseTo(100 * DEG, 14);
    expect(keys.down('ArrowRight', 'ArrowRight', false, true).changed).toBe(false);
    expect(keys.up('ArrowRight')).toBe(true);
    expect(keys.rates()).toBeNull();
    expect(keys.up('ArrowRight')).toBe(false);
  });

  it('adds held keys up, and releases by the physical key whatever value its release carries', () => {
    const keys = new KeyHold();
    keys.down('ArrowRight', 'ArrowRight', false, true);
    keys.down('ArrowUp', 'ArrowUp', true, true);
    keys.down('Equal', '+', true, true);
    const r = keys.rates()!;
    expect(r.dAzimuth).toBeCloseTo(100 * DEG, 14);
    expect(r.dElevation).toBe(0);
    expect(r.dy).toBeCloseTo(2, 14);
    expect(r.lnZoom).toBeCloseTo(20 * Math.log(1.2), 14);
    // Shift went up before the '+' did: its release reads '=', the same physical key.
    expect(keys.up('Equal')).toBe(true);
    expect(keys.rates()!.lnZoom).toBe(0);
    expect(keys.size).toBe(2);
    expect(keys.clear()).toBe(true);
    expect(keys.clear()).toBe(false);
    expect(keys.rates()).toBeNull();
  });

  it('never holds a reset, and ignores keys that are not the view’s', () => {
    const keys = new KeyHold();
    expect(keys.down('Digit0', '0', false, true)).toEqual({ handled: true, step: null, changed: false });
    expect(keys.down('KeyA', 'a', false, true)).toEqual({ handled: false, step: null, changed: false });
    expect(keys.down('KeyA', 'a', false, false).handled).toBe(false);
    expect(keys.rates()).toBeNull();
  });
});

describe('moveByRates', () => {
  it('moves the view by the held keys’ speeds: a second of frames is HOLD_STEPS_PER_S steps, zoom multiplying', () => {
    const keys = new KeyHold();
    keys.down('ArrowLeft', 'ArrowLeft', false, true);
    keys.down('Minus', '-', false, true);
    const v = recordingView();
    // A second in uneven frames, as a busy display gives them.
    for (const dt of [0.016, 0.017, 0.05, 0.2, 0.017, 0.7]) moveByRates(v, keys.rates()!, dt);
    expect(v.azimuth).toBeCloseTo(-HOLD_STEPS_PER_S * 5 * DEG, 12);
    expect(v.zoom).toBeCloseTo(1.2 ** -HOLD_STEPS_PER_S, 12);
    expect(v.elevation).toBe(0);
    // Only the calls a speed asks for: no pan.
    expect(v.calls).not.toContain('pan');
  });

  it('applyMove makes each kind of step', () => {
    const v = recordingView();
    const moves: ViewMove[] = [
      { op: 'orbit', dAzimuth: 0.1, dElevation: -0.2 },
      { op: 'pan', dx: 0.3, dy: 0.4 },
      { op: 'zoom', factor: 2 },
      { op: 'reset' },
    ];
    for (const m of moves) applyMove(v, m);
    expect([v.azimuth, v.elevation, v.x, v.y, v.zoom, v.resets]).toEqual([0.1, -0.2, 0.3, 0.4, 2, 1]);
  });
});
