import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE, reducer } from '../../../src/shared/state/appState';
import type { Action } from '../../../src/shared/state/appState';
import {
  DEFAULT_SYN_PATH,
  MAX_TARGETS,
  SYN_PATH_URL_KEYS,
  synPathReducer,
  targetsCodec,
} from '../../../src/shared/state/slices/synthesisSlice';
import { parseUrl, serializeState } from '../../../src/shared/url/url';

const quiet = () => undefined;

describe('synPathReducer', () => {
  it('returns the same object for an action it does not handle, or a value it already has', () => {
    expect(synPathReducer(DEFAULT_SYN_PATH, { type: 'setTheta2', deg: 10 })).toBe(DEFAULT_SYN_PATH);
    expect(synPathReducer(DEFAULT_SYN_PATH, { type: 'setTiming', timing: 'free' })).toBe(DEFAULT_SYN_PATH);
    expect(synPathReducer(DEFAULT_SYN_PATH, { type: 'setSynthesisMode', mode: 'path' })).toBe(DEFAULT_SYN_PATH);
  });

  it('sets the targets (copied, at most MAX_TARGETS) and goes back to the best candidate', () => {
    const picked = synPathReducer(DEFAULT_SYN_PATH, { type: 'chooseCandidate', index: 3 });
    const many = Array.from({ length: MAX_TARGETS + 5 }, (_, i) => ({ x: i, y: -i }));
    const next = synPathReducer(picked, { type: 'setTargets', targets: many });
    expect(next.targets).toHaveLength(MAX_TARGETS);
    expect(next.targets[0]).not.toBe(many[0]);
    expect(next.chosen).toBe(0);
  });

  it('sets timing, step, given angles, bounds, input, seed and mode', () => {
    let s = DEFAULT_SYN_PATH;
    s = synPathReducer(s, { type: 'setTiming', timing: 'given' });
    s = synPathReducer(s, { type: 'setTimingStep', stepDeg: -15 });
    s = synPathReducer(s, { type: 'setGivenTheta2', theta2Deg: [0, 30] });
    s = synPathReducer(s, { type: 'setPathBounds', bounds: { boundLength: 12, boundCoupler: null } });
    s = synPathReducer(s, { type: 'setPathInput', input: 'any' });
    s = synPathReducer(s, { type: 'setPathSeed', seed: 7 });
    s = synPathReducer(s, { type: 'setSynthesisMode', mode: 'function' });
    expect(s).toMatchObject({
      timing: 'given',
      timingStepDeg: -15,
      givenTheta2Deg: [0, 30],
      boundLength: 12,
      boundCoupler: null,
      input: 'any',
      seed: 7,
      mode: 'function',
    });
  });

  it('removes a target and its given θ2 in one action: one undo step (issue 34, 7)', () => {
    const s = {
      ...DEFAULT_SYN_PATH,
      targets: [
        { x: 0, y: 0 },
        { x: 1, y: 1 },
        { x: 2, y: 0 },
      ],
      givenTheta2Deg: [10, 20, 30],
      chosen: 2,
    };
    const next = synPathReducer(s, { type: 'removeTarget', index: 1 });
    expect(next.targets).toEqual([
      { x: 0, y: 0 },
      { x: 2, y: 0 },
    ]);
    expect(next.givenTheta2Deg).toEqual([10, 30]);
    expect(next.chosen).toBe(0);
    expect(synPathReducer(s, { type: 'removeTarget', index: 3 })).toBe(s);
  });

  it('is composed into the app reducer', () => {
    const next = reducer(DEFAULT_STATE, { type: 'setTargets', targets: [{ x: 1, y: 2 }] });
    expect(next.synPath.targets).toEqual([{ x: 1, y: 2 }]);
    expect(next.design).toBe(DEFAULT_STATE.design);
  });
});

describe('the chosen candidate (issue 34, item 13)', () => {
  it('is kept by the URL as cd and set back to the best by every edit of the task or the seed', () => {
    const chosen = reducer(DEFAULT_STATE, { type: 'chooseCandidate', index: 4 });
    expect(new URLSearchParams(serializeState(chosen)).get('cd')).toBe('4');
    expect(parseUrl('cd=4', DEFAULT_STATE, quiet).state.synPath.chosen).toBe(4);
    expect(parseUrl('cd=64', DEFAULT_STATE, quiet).ignored.map((i) => i.key)).toEqual(['cd']);
    const edits: Action[] = [
      { type: 'setTargets', targets: [{ x: 1, y: 2 }] },
      { type: 'removeTarget', index: 0 },
      { type: 'setTiming', timing: 'step' },
      { type: 'setTimingStep', stepDeg: 20 },
      { type: 'setGivenTheta2', theta2Deg: [10] },
      { type: 'setPathBounds', bounds: { boundLength: 5 } },
      { type: 'setPathInput', input: 'any' },
      { type: 'setPathSeed', seed: 7 },
    ];
    const withTarget = reducer(chosen, { type: 'setTargets', targets: [{ x: 1, y: 2 }] });
    const again = reducer(withTarget, { type: 'chooseCandidate', index: 4 });
    for (const edit of edits) expect(reducer(again, edit).synPath.chosen, edit.type).toBe(0);
    // What is not the task keeps it: the mode, and setting a field to the value it has.
    expect(reducer(again, { type: 'setSynthesisMode', mode: 'motion' }).synPath.chosen).toBe(4);
    expect(reducer(again, { type: 'setPathSeed', seed: 1 }).synPath.chosen).toBe(4);
  });
});

describe('synthesis URL keys', () => {
  it('writes nothing for the default slice', () => {
    const params = new URLSearchParams(serializeState(DEFAULT_STATE));
    for (const k of SYN_PATH_URL_KEYS) expect(params.has(k.name), k.name).toBe(false);
  });

  it('round-trips a full task through the URL', () => {
    const synPath = {
      ...DEFAULT_SYN_PATH,
      mode: 'path' as const,
      targets: [
        { x: 1.5, y: -2 },
        { x: 0.1, y: 3e-7 },
        { x: -4, y: 10 },
      ],
      timing: 'given' as const,
      timingStepDeg: 12.5,
      givenTheta2Deg: [0, 45.5, -90],
      boundLength: 20,
      boundCoupler: 7,
      pivotBox: { min: { x: -5, y: -6 }, max: { x: 5, y: 6 } },
      input: 'any' as const,
      seed: 42,
      chosen: 3,
    };
    const state = { ...DEFAULT_STATE, synPath, shell: { ...DEFAULT_STATE.shell, page: 'synthesis' as const } };
    const back = parseUrl(serializeState(state), DEFAULT_STATE, quiet);
    expect(back.ignored).toEqual([]);
    expect(back.state.synPath).toEqual(synPath);
    expect(back.state.shell.page).toBe('synthesis');
  });

  it('keeps a θ2 not given (NaN) as an empty item of tt, never as 0 (issue 34, 3)', () => {
    const r = parseUrl('page=syn&tg=0,0;1,1;2,0&tm=given&tt=10,,30', DEFAULT_STATE, quiet);
    expect(r.ignored).toEqual([]);
    expect(r.state.synPath.givenTheta2Deg).toEqual([10, NaN, 30]);
    expect(new URLSearchParams(serializeState(r.state)).get('tt')).toBe('10,,30');
    expect(parseUrl('page=syn&tt=10,x', DEFAULT_STATE, quiet).ignored).toHaveLength(1);
  });

  it('reads page=syn, syn=fn and tg/tm/ts as the issue writes them', () => {
    const r = parseUrl('page=syn&syn=fn&tg=0,0;1,2.5;-3,4&tm=step&ts=20', DEFAULT_STATE, quiet);
    expect(r.ignored).toEqual([]);
    expect(r.state.shell.page).toBe('synthesis');
    expect(r.state.synPath.mode).toBe('function');
    expect(r.state.synPath.targets).toEqual([
      { x: 0, y: 0 },
      { x: 1, y: 2.5 },
      { x: -3, y: 4 },
    ]);
    expect(r.state.synPath.timing).toBe('step');
    expect(r.state.synPath.timingStepDeg).toBe(20);
  });

  it('reads syn=function as syn=fn and writes the canonical syn=fn back', () => {
    for (const text of ['fn', 'function']) {
      const r = parseUrl(`page=syn&syn=${text}`, DEFAULT_STATE, quiet);
      expect(r.ignored).toEqual([]);
      expect(r.state.synPath.mode).toBe('function');
      expect(new URLSearchParams(serializeState(r.state)).get('syn')).toBe('fn');
    }
  });

  it('lists every syn value in docs/instructors.md', () => {
    const docs = readFileSync(new URL('../../../docs/instructors.md', import.meta.url), 'utf8');
    const line = /`syn` \(([^)]*)\)/.exec(docs)?.[1] ?? '';
    const listed = line.split(/[^a-z]+/);
    const syn = SYN_PATH_URL_KEYS.find((k) => k.name === 'syn');
    for (const text of ['path', 'motion', 'fn', 'function', 'nine']) {
      expect(syn?.parse(text).ok).toBe(true);
      expect(listed).toContain(text);
    }
  });

  it('ignores a bad value with the reason, keeping the default', () => {
    const r = parseUrl('tg=1,2;x,3&ts=0&bp=1,1,0,0', DEFAULT_STATE, quiet);
    expect(r.state.synPath).toEqual(DEFAULT_SYN_PATH);
    expect(r.ignored.map((p) => [p.key, p.why])).toEqual([
      ['tg', 'point 2 ("x,3") is not x,y'],
      ['ts', 'expected a nonzero step in degrees from -180 to 180'],
      ['bp', 'expected auto or x0,y0,x1,y1 with x0 < x1 and y0 < y1'],
    ]);
  });
});

describe('targetsCodec', () => {
  it('refuses more than MAX_TARGETS points, points without two coordinates, hex and Infinity', () => {
    const many = Array.from({ length: MAX_TARGETS + 1 }, () => '1,1').join(';');
    expect(targetsCodec.parse(many).ok).toBe(false);
    expect(targetsCodec.parse('0x10,1').ok).toBe(false);
    expect(targetsCodec.parse('1,2;3')).toEqual({ ok: false, why: 'point 2 ("3") is not x,y' });
    expect(targetsCodec.parse('1,2,3').ok).toBe(false);
    expect(targetsCodec.parse('Infinity,1').ok).toBe(false);
    expect(targetsCodec.parse('')).toEqual({ ok: true, value: [] });
  });
});

describe('design placement keys', () => {
  it('writes ox, oy and og only when the placement is not the default, and reads them back', () => {
    expect(serializeState(DEFAULT_STATE)).not.toMatch(/\b(ox|oy|og)=/);
    const placed = {
      ...DEFAULT_STATE,
      design: { ...DEFAULT_STATE.design, placement: { x: 2.5, y: -1, angleDeg: -30.25 } },
    };
    const text = serializeState(placed);
    expect(text).toMatch(/ox=2\.5/);
    expect(parseUrl(text, DEFAULT_STATE, quiet).state.design.placement).toEqual({ x: 2.5, y: -1, angleDeg: -30.25 });
  });

  it('goes back to the default placement with a preset', () => {
    const placed = reducer(DEFAULT_STATE, { type: 'setPlacement', placement: { x: 1, y: 2, angleDeg: 3 } });
    const preset = reducer(placed, {
      type: 'applyPreset',
      linkage: { r1: 4, r2: 1, r3: 4, r4: 3 },
      theta2Deg: 0,
      branch: 'open',
      coupler: { distance: 1, angleDeg: 0 },
    });
    expect(preset.design.placement).toEqual({ x: 0, y: 0, angleDeg: 0 });
  });
});
