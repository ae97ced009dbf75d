import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE, reducer } from '../../../../src/shared/state/appState';
import type { AppState } from '../../../../src/shared/state/appState';
import type { SynMotionState } from '../../../../src/shared/state/slices/synMotionSlice';
import {
  DEFAULT_POSES_FIVE,
  DEFAULT_SYN_MOTION,
  picksCodec,
  posesCodec,
} from '../../../../src/shared/state/slices/synMotionSlice';
import { parseUrl, serializeState } from '../../../../src/shared/url/url';

const quiet = () => {};
const withMotion = (patch: Partial<SynMotionState>): AppState => ({
  ...DEFAULT_STATE,
  synMotion: { ...DEFAULT_SYN_MOTION, ...patch },
});

describe('synMotionReducer', () => {
  it('starts from three poses of a crank-rocker with its moving pivots', () => {
    expect(DEFAULT_STATE.synMotion.poses).toEqual(DEFAULT_POSES_FIVE.slice(0, 3));
    expect(DEFAULT_STATE.synMotion.pivotChoice).toBe('moving');
  });

  it('moves one pose, keeping its angle in (−180°, 180°], and returns the same state for no change', () => {
    const s = reducer(DEFAULT_STATE, { type: 'setSynPose', index: 1, pose: { x: 3, y: 4, angleDeg: 270 } });
    expect(s.synMotion.poses[1]).toEqual({ x: 3, y: 4, angleDeg: -90 });
    expect(s.synMotion.poses[0]).toBe(DEFAULT_STATE.synMotion.poses[0]);
    expect(s.design).toBe(DEFAULT_STATE.design);
    const same = reducer(DEFAULT_STATE, { type: 'setSynPose', index: 0, pose: { ...DEFAULT_POSES_FIVE[0] } });
    expect(same).toBe(DEFAULT_STATE);
    expect(reducer(DEFAULT_STATE, { type: 'setSynPose', index: 7, pose: { x: 0, y: 0, angleDeg: 0 } })).toBe(
      DEFAULT_STATE,
    );
  });

  it('starts the method afresh when the number of poses changes, and not when a pose moves', () => {
    const picked = reducer(withMotion({ poses: DEFAULT_POSES_FIVE.slice(0, 4), choice: 2 }), {
      type: 'pickSynDyad',
      center: { x: 1, y: 2 },
    });
    const moved = reducer(picked, { type: 'setSynPose', index: 0, pose: { x: 0, y: 0, angleDeg: 30 } });
    expect(moved.synMotion.dyadPicks).toEqual([{ x: 1, y: 2 }]);
    const fewer = reducer(moved, { type: 'setSynPoses', poses: DEFAULT_POSES_FIVE.slice(0, 3) });
    expect(fewer.synMotion).toMatchObject({ dyadPicks: [], choice: 0 });
  });

  it('keeps the last two dyad picks', () => {
    let s = withMotion({ poses: DEFAULT_POSES_FIVE.slice(0, 4) });
    for (const x of [1, 2, 3]) s = reducer(s, { type: 'pickSynDyad', center: { x, y: 0 } });
    expect(s.synMotion.dyadPicks.map((p) => p.x)).toEqual([2, 3]);
    expect(reducer(s, { type: 'clearSynDyads' }).synMotion.dyadPicks).toEqual([]);
  });
});

describe('Motion URL keys', () => {
  it('writes nothing for the defaults and reads back every key it writes', () => {
    expect(serializeState(DEFAULT_STATE)).not.toMatch(/(^|&)(ps|pc|pv|dy|mc|mg|mq)=/);
    const s = withMotion({
      poses: [
        { x: 1.25, y: -2, angleDeg: 10 },
        { x: 0, y: 3.5, angleDeg: -170.5 },
        { x: 1e-7, y: 12345.678, angleDeg: 180 },
        { x: -4, y: 0.1, angleDeg: 0.000000001 },
      ],
      pivotChoice: 'fixed',
      pivots: [
        { x: 0.5, y: 0.25 },
        { x: -1, y: 2 },
      ],
      dyadPicks: [{ x: 3, y: -4 }],
      choice: 3,
      groundLength: 7.5,
      timeRatio: 1.25,
    });
    const text = serializeState(s);
    for (const k of ['ps', 'pc', 'pv', 'dy', 'mc', 'mg', 'mq']) expect(new URLSearchParams(text).has(k), k).toBe(true);
    const back = parseUrl(text, DEFAULT_STATE, quiet);
    expect(back.ignored).toEqual([]);
    expect(back.state.synMotion).toEqual(s.synMotion);
  });

  it('reads ps=x,y,deg;… and normalises the angles', () => {
    const r = parseUrl('ps=0,0,0;1,0,370;2,1,-190', DEFAULT_STATE, quiet);
    expect(r.ignored).toEqual([]);
    expect(r.state.synMotion.poses).toEqual([
      { x: 0, y: 0, angleDeg: 0 },
      { x: 1, y: 0, angleDeg: 10 },
      { x: 2, y: 1, angleDeg: 170 },
    ]);
    expect(parseUrl('mg=auto', DEFAULT_STATE, quiet).state.synMotion.groundLength).toBeNull();
    expect(parseUrl('dy=none', withMotion({ dyadPicks: [{ x: 1, y: 1 }] }), quiet).state.synMotion.dyadPicks).toEqual(
      [],
    );
  });

  it.each([
    ['ps', '1,2,3', /expected 2 to 20 poses/],
    ['ps', Array.from({ length: 21 }, (_, i) => `${i},${i},${i}`).join(';'), /expected 2 to 20 poses.*got 21/],
    ['ps', '0,0,0;1,1', /pose 2 must be 3 comma-separated numbers, got 2/],
    ['ps', '0,0,0;1,abc,2', /pose 2: "abc" is not a number/],
    ['ps', '0,0,0;1,1e12,2', /pose 2: a value is beyond/],
    ['ps', '0,0,0;Infinity,1,2', /pose 2: "Infinity" is not a number/],
    ['pc', 'sideways', /expected moving or fixed/],
    ['pv', '1,2', /expected 2 to 2 pivots/],
    ['dy', '1,2;3,4;5,6', /expected 0 to 2 picks/],
    ['mc', '15', /whole number from 0 to 14/],
    ['mc', '-1', /whole number from 0 to 14/],
    ['mg', '0', /auto or a length above 0/],
    ['mg', '-3', /auto or a length above 0/],
    ['mq', '0.5', /time ratio from 1 to 10/],
    ['mq', '11', /time ratio from 1 to 10/],
  ])('refuses %s=%s, saying why, and keeps the default', (key, value, why) => {
    const r = parseUrl(`${key}=${encodeURIComponent(value)}`, DEFAULT_STATE, quiet);
    expect(r.ignored.map((p) => p.key)).toEqual([key]);
    expect(r.ignored[0].why).toMatch(why);
    expect(r.state).toEqual(DEFAULT_STATE);
  });

  it('reads 6 to 20 poses and a choice up to 14 (least squares, issue 34 item 9)', () => {
    const twenty = Array.from({ length: 20 }, (_, i) => ({ x: i, y: i / 2, angleDeg: 2 * i }));
    const text = twenty.map((p) => `${p.x},${p.y},${p.angleDeg}`).join(';');
    const r = parseUrl(`ps=${encodeURIComponent(text)}&mc=14`, DEFAULT_STATE, quiet);
    expect(r.ignored).toEqual([]);
    expect(r.state.synMotion.poses).toEqual(twenty);
    expect(r.state.synMotion.choice).toBe(14);
  });

  it('rounds a dragged pose to 10 significant digits and 1e-9° on the way out', () => {
    const text = posesCodec.format([
      { x: 0.1 + 0.2, y: 1 / 3, angleDeg: 12.3456789012345 },
      { x: 2, y: 2, angleDeg: 0 },
    ]);
    expect(text).toBe('0.3,0.3333333333,12.345678901;2,2,0');
    expect(picksCodec.format([])).toBe('none');
  });
});
