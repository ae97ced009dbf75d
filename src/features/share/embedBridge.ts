import type { EmbedValue } from './embedMessages';
import { readSetState, stateEvent } from './embedMessages';

/** Where a patch of URL keys came from: the parent window's set-state command, or the element's attributes. */
export type PatchSource = 'parent' | 'attribute';

/** How the widget talks to its host: it publishes its state as URL keys and receives patches of them. */
export interface EmbedBridge {
  /** Called with the state's URL values when they change (first: the values the widget started with). */
  publish(values: Record<string, EmbedValue>, first: boolean): void;
  /** Registers the widget's handler for patches from the host; returns the function that removes it. */
  listen(onPatch: (patch: Record<string, unknown>, source: PatchSource) => void): () => void;
}

/**
 * The bridge of the iframe widget (embed.html): posts `{ source: 'fourbar-lab', type: 'state', state }` to the
 * parent window, and hands on `{ target: 'fourbar-lab', type: 'set-state', state }` commands only when they come
 * from the parent window itself. Outside a frame it does nothing. The state is not secret, so it is posted to
 * any origin ('*'); commands are checked by source, their values by the URL codecs (useEmbedMessages).
 */
export function frameBridge(win: Window = window): EmbedBridge {
  const framed = win.parent !== win;
  return {
    publish(values) {
      if (framed) win.parent.postMessage(stateEvent(values), '*');
    },
    listen(onPatch) {
      if (!framed) return () => undefined;
      const onMessage = (e: MessageEvent) => {
        if (e.source !== win.parent) return;
        const patch = readSetState(e.data);
        if (patch) onPatch(patch, 'parent');
      };
      win.addEventListener('message', onMessage);
      return () => win.removeEventListener('message', onMessage);
    },
  };
}
