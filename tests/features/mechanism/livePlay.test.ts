import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { MECHANISM_TEMPLATES } from '../../../src/mechanism';
import { createPlayheadSource, throttledSubscribe } from '../../../src/features/mechanism/livePlayhead';
import { DRAG_REST_MS, nextJointDrag, restDelayMs } from '../../../src/features/mechanism/useJointDrag';
import type { JointDrag } from '../../../src/features/mechanism/useJointDrag';
import { playFrame } from '../../../src/features/mechanism/mechDriveStep';
import { moveJoint } from '../../../src/features/mechanism/specEdits';

// What keeps a frame of Play and a move of a drag cheap on the Mechanisms page (issue 33's speed targets): the
// playhead lives in a source its few readers subscribe to (the page re-renders only when Play turns), text readouts
// follow it a few times a second, and a drag draws its linkage at each move, sweeps it at rest and commits it once.

describe('createPlayheadSource', () => {
  it('tells its readers of a new playhead, not of the same one set again, and stops telling on unsubscribe', () => {
    const source = createPlayheadSource();
    const heard: (number | null)[] = [];
    const off = source.subscribe(() => heard.push(source.get()?.input ?? null));
    expect(source.get()).toBeNull();
    const p = { input: 0.5, direction: 1 as const, limitAt: null };
    source.set(p);
    source.set(p);
    source.set({ ...p, input: 0.6 });
    source.set(null);
    off();
    source.set(p);
    expect(heard).toEqual([0.5, 0.6, null]);
  });
});

describe('throttledSubscribe', () => {
  beforeEach(() => {
    vi.useFakeTimers();
  });
  afterEach(() => {
    vi.useRealTimers();
  });

  it('calls a reader at most once per interval, and once more after the last change of a burst', () => {
    const source = createPlayheadSource();
    const calls: number[] = [];
    const off = throttledSubscribe(source.subscribe, 200)(() => calls.push(Date.now()));
    const t0 = Date.now();
    // 60 frames a second for one second: 60 changes.
    for (let k = 1; k <= 60; k++) {
      source.set({ input: k, direction: 1, limitAt: null });
      vi.advanceTimersByTime(1000 / 60);
    }
    vi.advanceTimersByTime(1000);
    off();
    const at = calls.map((t) => t - t0);
    // The first change at once, then one per 200 ms: 0, 200, 400, 600, 800, and the trailing one at 1000.
    expect(at.length).toBeGreaterThanOrEqual(5);
    expect(at.length).toBeLessThanOrEqual(6);
    for (let i = 1; i < at.length; i++) expect(at[i] - at[i - 1]).toBeGreaterThanOrEqual(200);
    // The last change (at about 983 ms) is heard: a reader ends on the playhead where it stopped.
    expect(at[at.length - 1]).toBeGreaterThanOrEqual(983);
  });

  it('hears nothing after unsubscribing, even a pending trailing call', () => {
    const source = createPlayheadSource();
    const listener = vi.fn();
    const off = throttledSubscribe(source.subscribe, 200)(listener);
    source.set({ input: 1, direction: 1, limitAt: null });
    source.set({ input: 2, direction: 1, limitAt: null });
    off();
    vi.advanceTimersByTime(1000);
    expect(listener).toHaveBeenCalledTimes(1);
  });

  it('refuses an interval that is not a positive finite number, naming it', () => {
    const source = createPlayheadSource();
    expect(() => throttledSubscribe(source.subscribe, 0)).toThrow(/everyMs.*got 0/);
    expect(() => throttledSubscribe(source.subscribe, Number.NaN)).toThrow(/everyMs.*got NaN/);
  });
});

describe('playFrame', () => {
  it('turns (the page re-renders) only at a rocking range’s ends: 2 of 400 frames of 1° over [−1, 1] rad', () => {
    const range: [number, number] = [-1, 1];
    let p = { input: 0, direction: 1 as 1 | -1, limitAt: null as number | null };
    const turns: number[] = [];
    const delta = Math.PI / 180;
    for (let k = 0; k < 400; k++) {
      const { next, turned } = playFrame(p, delta, range, false);
      if (turned) turns.push(next.input);
      p = next;
    }
    // From 0 up to 1 (58 frames), back down to −1 (about 115 frames), up again to 1: three ends met in 400 frames.
    expect(turns).toEqual([1, -1, 1]);
    expect(p.input).toBeGreaterThanOrEqual(-1);
    expect(p.input).toBeLessThanOrEqual(1);
  });

  it('never turns on a full turn, wrapping into [−π, π)', () => {
    let p = { input: 3, direction: 1 as 1 | -1, limitAt: null as number | null };
    for (let k = 0; k < 50; k++) {
      const { next, turned } = playFrame(p, 0.3, [-Math.PI, Math.PI], true);
      expect(turned).toBe(false);
      expect(next.input).toBeGreaterThanOrEqual(-Math.PI);
      expect(next.input).toBeLessThan(Math.PI);
      p = next;
    }
  });
});

describe('nextJointDrag', () => {
  const stored = MECHANISM_TEMPLATES.jansen.spec;
  const g = stored.joints.find((j) => j.id === 'G')!;
  const moved = (dx: number) => moveJoint(stored, 'G', g.x + dx, g.y);

  it('draws each move without analysing it, analyses the drawn spec at rest, and commits it once on release', () => {
    let drag: JointDrag | null = nextJointDrag(null, { type: 'grab', stored }).drag;
    expect(drag).toEqual({ from: stored, now: stored, analysed: stored });
    const a = moved(0.1);
    const b = moved(0.2);
    for (const spec of [a, b]) {
      const r = nextJointDrag(drag, { type: 'move', spec });
      expect(r.commit).toBeNull();
      drag = r.drag;
    }
    expect(drag!.now).toBe(b);
    expect(drag!.analysed).toBe(stored);
    drag = nextJointDrag(drag, { type: 'rest' }).drag;
    expect(drag!.analysed).toBe(b);
    const end = nextJointDrag(drag, { type: 'release' });
    expect(end).toEqual({ drag: null, commit: b });
  });

  it('commits nothing for a grab let go without a move, and ignores moves and rests with no drag on', () => {
    const drag = nextJointDrag(null, { type: 'grab', stored }).drag;
    expect(nextJointDrag(drag, { type: 'release' })).toEqual({ drag: null, commit: null });
    expect(nextJointDrag(null, { type: 'move', spec: moved(1) })).toEqual({ drag: null, commit: null });
    expect(nextJointDrag(null, { type: 'rest' })).toEqual({ drag: null, commit: null });
  });

  it('keeps the same drag object for a rest with nothing new (no re-render)', () => {
    const drag = nextJointDrag(null, { type: 'grab', stored }).drag;
    expect(nextJointDrag(drag, { type: 'rest' }).drag).toBe(drag);
    expect(nextJointDrag(drag, { type: 'move', spec: stored }).drag).toBe(drag);
  });
});

describe('restDelayMs', () => {
  it('is the rest time while moves come often, and twice the median gap when they come slower', () => {
    expect(restDelayMs([], DRAG_REST_MS)).toBe(DRAG_REST_MS);
    expect(restDelayMs([16, 17, 16, 18, 16], 250)).toBe(250);
    // A busy machine: a move every 300 ms or so (one 20 ms and one 2 s gap among them do not move the median).
    expect(restDelayMs([300, 20, 310, 2000, 290], 250)).toBe(600);
    // Only the latest five gaps count: the slow start is forgotten.
    expect(restDelayMs([900, 900, 900, 900, 900, 900, 16, 16, 16, 16, 16], 250)).toBe(250);
    // An even count: the mean of the two middle gaps.
    expect(restDelayMs([200, 400], 100)).toBe(600);
  });

  it('refuses a rest time that is not a positive finite number, naming it', () => {
    expect(() => restDelayMs([], 0)).toThrow(/restMs.*got 0/);
    expect(() => restDelayMs([], Infinity)).toThrow(/restMs.*got Infinity/);
  });
});
