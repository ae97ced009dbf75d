import { describe, expect, it } from 'vitest';
import type { Action, AppState } from '../../../src/shared/state/appState';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import { appHistoryReducer, appStepKey, carryPresent } from '../../../src/shared/state/appHistory';
import type { History } from '../../../src/shared/state/history';
import { canUndo, initHistory } from '../../../src/shared/state/history';
import { withFields } from './stateFixtures';

const R2_3 = { ...DEFAULT_STATE.design.linkage, r2: 3 };

function apply(h: History<AppState>, action: Action, at = 0, gesture: number | null = null): History<AppState> {
  return appHistoryReducer(h, { type: 'apply', action, at, gesture });
}

describe('appStepKey', () => {
  it('gives changes of one field the same key whatever the value', () => {
    expect(appStepKey({ type: 'setLength', field: 'r2', value: 2 })).toBe(
      appStepKey({ type: 'setLength', field: 'r2', value: 7.25 }),
    );
    expect(appStepKey({ type: 'setCoupler', coupler: { distance: 1 } })).toBe(
      appStepKey({ type: 'setCoupler', coupler: { distance: 3 } }),
    );
  });

  it('gives other fields and other choices their own keys', () => {
    expect(appStepKey({ type: 'setLength', field: 'r2', value: 2 })).not.toBe(
      appStepKey({ type: 'setLength', field: 'r3', value: 2 }),
    );
    expect(appStepKey({ type: 'setBranch', branch: 'open' })).not.toBe(
      appStepKey({ type: 'setBranch', branch: 'crossed' }),
    );
    expect(appStepKey({ type: 'setFlag', flag: 'showGrid', value: true })).not.toBe(
      appStepKey({ type: 'setFlag', flag: 'showGrid', value: false }),
    );
    expect(appStepKey({ type: 'setCoupler', coupler: { distance: 1 } })).not.toBe(
      appStepKey({ type: 'setCoupler', coupler: { angleDeg: 1 } }),
    );
  });

  it('makes no step of Play frames, Play, the view, the language or the page', () => {
    const skipped: Action[] = [
      { type: 'animate', theta2Deg: 50, direction: 1, branch: 'open' },
      { type: 'setPlaying', playing: true },
      { type: 'setView', view: { zoom: 2, panX: 0, panY: 0 } },
      { type: 'setLocale', locale: 'zh-TW' },
      { type: 'setPage', page: 'lab' },
    ];
    for (const a of skipped) expect(appStepKey(a), a.type).toBeNull();
  });

  it('makes a step of every other change, a file opened (replace) included', () => {
    const steps: Action[] = [
      { type: 'setTheta2', deg: 90 },
      { type: 'setOmegaUnit', unit: 'rpm' },
      { type: 'setSamples', samples: 720 },
      { type: 'setLabStep', stepDeg: 5 },
      { type: 'replace', state: DEFAULT_STATE },
    ];
    for (const a of steps) expect(appStepKey(a), a.type).not.toBeNull();
  });
});

describe('carryPresent', () => {
  it('keeps the present language, page and view and pauses, and restores everything else', () => {
    const restored = withFields(DEFAULT_STATE, { linkage: R2_3, theta2Deg: 100, playing: true });
    const present = withFields(DEFAULT_STATE, {
      locale: 'zh-TW',
      page: 'lab',
      view: { zoom: 2, panX: 0.1, panY: 0 },
      playing: true,
    });
    expect(carryPresent(restored, present)).toEqual(
      withFields(DEFAULT_STATE, {
        linkage: R2_3,
        theta2Deg: 100,
        playing: false,
        locale: 'zh-TW',
        page: 'lab',
        view: { zoom: 2, panX: 0.1, panY: 0 },
      }),
    );
  });

  it('keeps the identity of the slices it does not change', () => {
    const restored = withFields(DEFAULT_STATE, { linkage: R2_3 });
    const out = carryPresent(restored, DEFAULT_STATE);
    expect(out.design).toBe(restored.design);
    expect(out.display).toBe(restored.display);
    expect(out.motion).toBe(restored.motion);
  });
});

describe('appHistoryReducer', () => {
  it('undoes a drag of A (one gesture of setTheta2) in one step, to θ2 exactly', () => {
    let h = initHistory(withFields(DEFAULT_STATE, { theta2Deg: 45.123456789 }));
    for (let i = 0; i < 200; i++) {
      h = apply(h, { type: 'setPlaying', playing: false }, i * 16, 4);
      h = apply(h, { type: 'setTheta2', deg: 45 + i * 0.7 }, i * 16, 4);
    }
    expect(h.past).toHaveLength(1);
    h = appHistoryReducer(h, { type: 'undo' });
    expect(h.present.motion.theta2Deg).toBe(45.123456789);
  });

  it('keeps Play frames out of the history: undo after Play restores the state before the last step', () => {
    let h = apply(initHistory(DEFAULT_STATE), { type: 'setLength', field: 'r2', value: 2.5 });
    h = apply(h, { type: 'setPlaying', playing: true }, 5000);
    for (let i = 1; i <= 50; i++)
      h = apply(h, { type: 'animate', theta2Deg: 45 + i, direction: 1, branch: 'open' }, 5000 + i * 200);
    expect(h.past).toHaveLength(1);
    h = appHistoryReducer(h, { type: 'undo' });
    expect(h.present.design.linkage.r2).toBe(2);
    expect(h.present.motion.playing).toBe(false);
    expect(canUndo(h)).toBe(false);
  });

  it('does not undo a language change', () => {
    let h = apply(initHistory(DEFAULT_STATE), { type: 'setLength', field: 'r1', value: 7 });
    h = apply(h, { type: 'setLocale', locale: 'zh-TW' }, 5000);
    h = appHistoryReducer(h, { type: 'undo' });
    expect(h.present.shell.locale).toBe('zh-TW');
    expect(h.present.design.linkage.r1).toBe(6);
  });
});
