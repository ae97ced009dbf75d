import { withFields } from './stateFixtures';
import { describe, expect, it, vi } from 'vitest';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import type { PlayFrame } from '../../../src/shared/state/playhead';
import { Playhead, playFrameOf, playBase, sameFrame, withFrame } from '../../../src/shared/state/playhead';

const f = (theta2Deg: number, direction: 1 | -1 = 1, branch: 'open' | 'crossed' = 'open'): PlayFrame => ({
  theta2Deg,
  direction,
  branch,
});

describe('playBase', () => {
  it('starts from the state when nothing plays ahead of it', () => {
    expect(playBase(f(10), null, null, [])).toEqual(f(10));
    expect(playBase(f(10), f(5), null, [])).toEqual(f(10));
  });

  it('keeps the playhead while the state lags behind it (unchanged, or showing a frame Play committed)', () => {
    // The state still shows what it showed at the previous frame.
    expect(playBase(f(10), f(10), f(42), [])).toEqual(f(42));
    // The state caught up with a frame Play committed a while ago: still no edit, the playhead is ahead.
    expect(playBase(f(30), f(10), f(42), [f(20), f(30)])).toEqual(f(42));
    // The first frame of Play has no previous state to compare with.
    expect(playBase(f(10), null, f(42), [])).toEqual(f(42));
  });

  it('takes an edited field from the state and the others from the playhead', () => {
    // The θ2 field was set to 200 while playing: Play goes on from there, same direction and branch.
    expect(playBase(f(200), f(10), f(42, -1, 'crossed'), [])).toEqual(f(200, -1, 'crossed'));
    // The direction was flipped: θ2 stays where the playhead is.
    expect(playBase(f(10, -1), f(10, 1), f(42), [])).toEqual(f(42, -1));
    // The branch was switched.
    expect(playBase(f(10, 1, 'crossed'), f(10), f(42), [f(5)])).toEqual(f(42, 1, 'crossed'));
  });
});

describe('withFrame', () => {
  it('returns the state itself when the frame is null or already its own', () => {
    expect(withFrame(DEFAULT_STATE, null)).toBe(DEFAULT_STATE);
    expect(withFrame(DEFAULT_STATE, playFrameOf(DEFAULT_STATE))).toBe(DEFAULT_STATE);
  });
  it('puts the frame over the state and keeps everything else', () => {
    const s = withFrame(DEFAULT_STATE, f(123.5, -1, 'crossed'));
    expect(playFrameOf(s)).toEqual(f(123.5, -1, 'crossed'));
    expect(s.design.linkage).toBe(DEFAULT_STATE.design.linkage);
    expect(withFields(s, { theta2Deg: 45, direction: 1, branch: 'open' })).toEqual(DEFAULT_STATE);
  });
});

describe('Playhead', () => {
  it('tells its subscribers when the frame changes, and only then', () => {
    const p = new Playhead();
    const heard = vi.fn();
    const stop = p.subscribe(heard);
    expect(p.get()).toBeNull();
    p.set(f(1));
    p.set(f(1)); // the same frame again: no news
    p.set(f(2));
    p.set(null);
    p.set(null);
    expect(heard).toHaveBeenCalledTimes(3);
    stop();
    p.set(f(3));
    expect(heard).toHaveBeenCalledTimes(3);
    expect(p.get()).toEqual(f(3));
  });
  it('keeps get() stable between sets (useSyncExternalStore needs a stable snapshot)', () => {
    const p = new Playhead();
    p.set(f(7));
    expect(p.get()).toBe(p.get());
    expect(sameFrame(p.get() ?? f(0), f(7))).toBe(true);
  });
});
