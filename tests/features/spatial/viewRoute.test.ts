import { describe, expect, it } from 'vitest';
import { chooseViewRoute } from '../../../src/features/spatial/viewRoute';

describe('chooseViewRoute', () => {
  it('draws in the worker where a canvas can be handed over, on the page after the worker failed, nowhere without WebGL', () => {
    expect(chooseViewRoute({ webgl: true, canTransfer: true, workerFailed: false })).toBe('worker');
    expect(chooseViewRoute({ webgl: true, canTransfer: false, workerFailed: false })).toBe('main');
    expect(chooseViewRoute({ webgl: true, canTransfer: true, workerFailed: true })).toBe('main');
    expect(chooseViewRoute({ webgl: false, canTransfer: true, workerFailed: false })).toBe('none');
  });
});
