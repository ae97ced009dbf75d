import { describe, expect, it } from 'vitest';
import { PLAY_COMMIT_MS, playCommitGapMs } from '../../../src/features/simulator/useAnimation';

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
