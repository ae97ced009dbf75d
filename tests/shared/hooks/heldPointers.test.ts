import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { followPointers } from '../../../src/shared/hooks/heldPointers';

/** A pointer event of type for pointer id (node has EventTarget and Event, not PointerEvent). */
const pointer = (type: string, pointerId: number) => Object.assign(new Event(type), { pointerId });

describe('followPointers', () => {
  let page: EventTarget;
  beforeEach(() => {
    page = new EventTarget();
    vi.stubGlobal('window', page);
  });
  afterEach(() => vi.unstubAllGlobals());

  it('holds from the first press to the last release, and calls press and release once each', () => {
    const press = vi.fn();
    const release = vi.fn();
    const followed = followPointers({ press, release });
    expect(followed.held()).toBe(false);
    page.dispatchEvent(pointer('pointerdown', 1));
    page.dispatchEvent(pointer('pointerdown', 2));
    expect(followed.held()).toBe(true);
    expect(press).toHaveBeenCalledTimes(1);
    page.dispatchEvent(pointer('pointerup', 1));
    expect(followed.held()).toBe(true);
    expect(release).not.toHaveBeenCalled();
    page.dispatchEvent(pointer('pointercancel', 2));
    expect(followed.held()).toBe(false);
    expect(release).toHaveBeenCalledTimes(1);
  });

  it('ignores a release of a pointer it never saw go down', () => {
    const release = vi.fn();
    followPointers({ release });
    page.dispatchEvent(pointer('pointerup', 7));
    expect(release).not.toHaveBeenCalled();
  });

  it('stops following once disposed', () => {
    const press = vi.fn();
    const followed = followPointers({ press });
    followed.dispose();
    page.dispatchEvent(pointer('pointerdown', 1));
    expect(followed.held()).toBe(false);
    expect(press).not.toHaveBeenCalled();
  });
});
