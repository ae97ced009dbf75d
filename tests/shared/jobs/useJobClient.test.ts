import { describe, expect, it } from 'vitest';
import { solverStatusText } from '../../../src/shared/jobs/useJobClient';
import { messagesEn } from '../../../src/shared/i18n/messagesEn';
import { messagesZhTw } from '../../../src/shared/i18n/messagesZhTw';

describe('solverStatusText', () => {
  it('says nothing while the first worker solves', () => {
    expect(solverStatusText('starting', null, messagesEn)).toBeNull();
    expect(solverStatusText('worker', null, messagesEn)).toBeNull();
  });

  it('tells a restart, a fallback after two stops, and a worker that never ran apart, in English', () => {
    expect(solverStatusText('restarted', 'stopped', messagesEn)).toBe('The solver worker stopped; restarted it.');
    expect(solverStatusText('main-thread', 'stopped', messagesEn)).toBe(
      'Solving on the main thread: the worker stopped twice.',
    );
    expect(solverStatusText('main-thread', 'unavailable', messagesEn)).toBe(
      'Web Worker unavailable here: solving on the main thread.',
    );
  });

  it('says the same in Traditional Chinese: restarted (重新啟動), main thread (主執行緒) after two stops (兩次)', () => {
    const restarted = solverStatusText('restarted', 'stopped', messagesZhTw)!;
    const twice = solverStatusText('main-thread', 'stopped', messagesZhTw)!;
    expect(restarted).toContain('重新啟動');
    expect(restarted).not.toContain('主執行緒');
    expect(twice).toContain('主執行緒');
    expect(twice).toContain('兩次');
    expect(solverStatusText('main-thread', 'unavailable', messagesZhTw)).toBe(messagesZhTw.solvingOnMainThread);
  });
});
