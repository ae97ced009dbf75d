import { describe, expect, it } from 'vitest';
import { PANEL_INTERVAL_MS, SpatialPlayhead } from '../../../src/features/spatial/spatialPlayhead';
import type { SpatialFrame } from '../../../src/features/spatial/spatialPlayhead';

const frame = (theta2Deg: number): SpatialFrame => ({ theta2Deg, branch: 'open', pose: null, muRad: null });

describe('SpatialPlayhead', () => {
  it('keeps every frame Play advances to, and shows the panels one at most every PANEL_INTERVAL_MS', () => {
    const p = new SpatialPlayhead();
    const heard: number[] = [];
    p.subscribe(() => heard.push(p.get()?.theta2Deg ?? Number.NaN));
    p.advance(frame(1), 1000);
    p.advance(frame(2), 1000 + PANEL_INTERVAL_MS / 2);
    expect(p.current()?.theta2Deg).toBe(2);
    expect(p.get()?.theta2Deg).toBe(1);
    p.advance(frame(3), 1000 + PANEL_INTERVAL_MS);
    expect(heard).toEqual([1, 3]);
    expect(p.get()).toBe(p.current());
  });

  it('shows a set frame (a step, the state taking over) at once, and null hands both back to the state', () => {
    const p = new SpatialPlayhead();
    let heard = 0;
    p.subscribe(() => heard++);
    p.advance(frame(10), 0);
    p.set(frame(11));
    expect(p.get()?.theta2Deg).toBe(11);
    expect(heard).toBe(2);
    p.set(null);
    expect(p.get()).toBeNull();
    expect(p.current()).toBeNull();
    // After a set, Play's next frame shows at once.
    p.advance(frame(12), 1);
    expect(p.get()?.theta2Deg).toBe(12);
  });
});
