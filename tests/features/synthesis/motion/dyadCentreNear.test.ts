import { describe, expect, it } from 'vitest';
import { dyadCentreNear } from '../../../../src/features/synthesis/motion/useMotionView';

const pair = (x: number, y: number) => ({ center: { x, y }, circle: { x: 0, y: 0 } });

describe('dyadCentreNear', () => {
  const samples = [pair(0, 0), pair(3, 4), pair(10, 0)];

  it('picks the nearest centre within reach', () => {
    expect(dyadCentreNear(samples, { x: 2.9, y: 4.2 }, 1)).toEqual({ x: 3, y: 4 });
    // (6, 0) is 5 from (3, 4) and 4 from (10, 0).
    expect(dyadCentreNear(samples, { x: 6, y: 0 }, 5)).toEqual({ x: 10, y: 0 });
  });

  it('takes a centre exactly at the reach (distance 5 to (3, 4) from the origin)', () => {
    expect(dyadCentreNear([pair(3, 4)], { x: 0, y: 0 }, 5)).toEqual({ x: 3, y: 4 });
  });

  it('is null when every centre is beyond reach, or there are none', () => {
    expect(dyadCentreNear(samples, { x: 6, y: -6 }, 1)).toBeNull();
    expect(dyadCentreNear([], { x: 0, y: 0 }, 100)).toBeNull();
  });
});
