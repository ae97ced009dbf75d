import { describe, expect, it } from 'vitest';
import { frameBridge } from '../../../src/features/share/embedBridge';

/** A fake window pair: the widget's window and its parent, with the message listeners the bridge adds. */
function fakeFrame() {
  const posted: { message: unknown; origin: string }[] = [];
  const parent = { postMessage: (message: unknown, origin: string) => posted.push({ message, origin }) };
  const listeners = new Set<(e: MessageEvent) => void>();
  const win = {
    parent,
    addEventListener: (_type: string, f: (e: MessageEvent) => void) => listeners.add(f),
    removeEventListener: (_type: string, f: (e: MessageEvent) => void) => listeners.delete(f),
  };
  const deliver = (data: unknown, source: unknown) => {
    for (const f of [...listeners]) f({ data, source } as MessageEvent);
  };
  return { win: win as unknown as Window, parent, posted, listeners, deliver };
}

const COMMAND = { target: 'fourbar-lab', type: 'set-state', state: { r3: 4 } };

describe('frameBridge', () => {
  it('hands on a set-state command only when it comes from the parent window itself', () => {
    const f = fakeFrame();
    const patches: unknown[] = [];
    frameBridge(f.win).listen((patch, source) => patches.push({ patch, source }));
    f.deliver(COMMAND, {}); // another window (a sibling frame, a popup)
    f.deliver(COMMAND, null); // no source at all
    f.deliver(COMMAND, f.win); // the widget's own window
    expect(patches).toEqual([]);
    f.deliver(COMMAND, f.parent);
    expect(patches).toEqual([{ patch: { r3: 4 }, source: 'parent' }]);
  });

  it('ignores messages from the parent that are not set-state commands of this widget', () => {
    const f = fakeFrame();
    const patches: unknown[] = [];
    frameBridge(f.win).listen((patch) => patches.push(patch));
    for (const data of [
      { ...COMMAND, target: 'other-widget' },
      { ...COMMAND, type: 'state' },
      { ...COMMAND, state: 'r3=4' },
      'set-state',
      null,
    ])
      f.deliver(data, f.parent);
    expect(patches).toEqual([]);
  });

  it('posts the state to the parent, and stops listening when the returned function is called', () => {
    const f = fakeFrame();
    const bridge = frameBridge(f.win);
    bridge.publish({ r1: 6 }, true);
    expect(f.posted).toEqual([{ message: { source: 'fourbar-lab', type: 'state', state: { r1: 6 } }, origin: '*' }]);
    const stop = bridge.listen(() => undefined);
    expect(f.listeners.size).toBe(1);
    stop();
    expect(f.listeners.size).toBe(0);
  });

  it('does nothing outside a frame (the window is its own parent)', () => {
    const listeners = new Set<unknown>();
    const win = {
      addEventListener: (_t: string, f: unknown) => listeners.add(f),
      removeEventListener: () => undefined,
    } as unknown as Window & { parent: Window };
    (win as { parent: Window }).parent = win;
    const bridge = frameBridge(win);
    bridge.listen(() => undefined);
    expect(listeners.size).toBe(0);
  });
});
