import { describe, expect, it } from 'vitest';
import {
  CommitPacer,
  PLAY_COMMIT_MAX_MS,
  PLAY_COMMIT_MS,
  playCommitGapMs,
} from '../../../src/features/simulator/commitPacer';

describe('playCommitGapMs: how often Play commits to the app state', () => {
  it('commits five times a second where a commit renders fast', () => {
    for (const ms of [0, 1, 10, 24]) expect(playCommitGapMs(ms)).toBe(PLAY_COMMIT_MS);
  });

  it('waits eight renders between commits on a slow device, so commits take about an eighth of the time', () => {
    expect(playCommitGapMs(50)).toBe(400);
    expect(playCommitGapMs(100)).toBe(800);
  });

  it('still commits once a second however slow the render, and ignores a measurement that is not a time', () => {
    expect(playCommitGapMs(500)).toBe(1000);
    expect(playCommitGapMs(Number.POSITIVE_INFINITY)).toBe(PLAY_COMMIT_MS);
    expect(playCommitGapMs(Number.NaN)).toBe(PLAY_COMMIT_MS);
    expect(playCommitGapMs(-5)).toBe(PLAY_COMMIT_MS);
  });
});

/** Feeds n frame intervals of the given lengths (cycled) to the pacer. */
function feed(pacer: CommitPacer, n: number, intervals: readonly number[]): void {
  for (let i = 0; i < n; i++) pacer.noteFrame(intervals[i % intervals.length]);
}

describe('CommitPacer: Play commits less often while the page drops frames', () => {
  it('keeps five commits a second while the page keeps up with a 60 Hz display', () => {
    const pacer = new CommitPacer();
    feed(pacer, 60, [16.7, 16.6, 16.8]);
    for (let i = 0; i < 5; i++) expect(pacer.nextGap(5)).toBe(PLAY_COMMIT_MS);
  });

  it('doubles the gap at each commit while frames are dropped (44 frames/s on 60 Hz), up to once a second', () => {
    const pacer = new CommitPacer();
    feed(pacer, 30, [16.7, 22.7, 22.7]);
    expect(pacer.nextGap(5)).toBe(400);
    expect(pacer.nextGap(5)).toBe(800);
    expect(pacer.nextGap(5)).toBe(PLAY_COMMIT_MAX_MS);
    expect(pacer.nextGap(5)).toBe(PLAY_COMMIT_MAX_MS);
  });

  it('halves it again once the page keeps up, and holds it in between (no see-saw)', () => {
    const pacer = new CommitPacer();
    feed(pacer, 30, [16.7, 22.7, 22.7]);
    pacer.nextGap(5);
    pacer.nextGap(5);
    expect(pacer.nextGap(5)).toBe(1000);
    // Mean 18.4 ms against 16.7: neither dropping (over 1.2x) nor keeping up (within 1.06x): held.
    feed(pacer, 30, [16.7, 19.25, 19.25]);
    expect(pacer.nextGap(5)).toBe(1000);
    feed(pacer, 30, [16.7, 16.8, 16.9]);
    expect(pacer.nextGap(5)).toBe(500);
    expect(pacer.nextGap(5)).toBe(250);
    expect(pacer.nextGap(5)).toBe(PLAY_COMMIT_MS);
  });

  it('counts whole refreshes by their mean: 40 frames/s on 60 Hz is more one-refresh intervals than two, and dropping', () => {
    const pacer = new CommitPacer();
    feed(pacer, 30, [16.7, 16.7, 16.7, 33.3, 33.3]);
    expect(pacer.nextGap(5)).toBe(400);
  });

  it('measures against the display: a steady 30 Hz display is keeping up, not dropping', () => {
    const pacer = new CommitPacer();
    feed(pacer, 60, [33.3, 33.4]);
    expect(pacer.nextGap(5)).toBe(PLAY_COMMIT_MS);
  });

  it('never goes under the render-based gap, waits for enough frames, ignores pauses, and resets', () => {
    const pacer = new CommitPacer();
    expect(pacer.nextGap(100)).toBe(800);
    feed(pacer, 14, [16.7, 40]);
    expect(pacer.nextGap(5)).toBe(PLAY_COMMIT_MS);
    const paused = new CommitPacer();
    feed(paused, 30, [16.7, 16.7, 5000]);
    expect(paused.nextGap(5)).toBe(PLAY_COMMIT_MS);
    feed(pacer, 30, [16.7, 40]);
    expect(pacer.nextGap(5)).toBe(400);
    pacer.reset();
    expect(pacer.nextGap(5)).toBe(PLAY_COMMIT_MS);
  });
});
