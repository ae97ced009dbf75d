import { useEffect, useEffectEvent, useRef } from 'react';
import type { Dispatch } from 'react';
import type { Action, AppState } from '../../shared/state/appState';
import { applyPatch, stateValues } from './embedMessages';
import type { LockableParam } from '../../shared/url/embedOptions';
import type { EmbedBridge, PatchSource } from './embedBridge';

/** Longest wait between a state change and its event, ms: at most five events a second, the last state always sent. */
export const STATE_EVENT_INTERVAL_MS = 200;

/**
 * Connects the widget to its host through a bridge: publishes the state's URL values (throttled, only when they
 * changed) and applies the host's patches through applyPatch. Patches from the parent window respect the locks;
 * attributes, which the page author writes, do not. Refused keys are reported on the console. A null bridge
 * does nothing.
 */
export function useEmbedMessages(
  bridge: EmbedBridge | null,
  state: AppState,
  dispatch: Dispatch<Action>,
  locked: readonly LockableParam[],
): void {
  const latest = useRef(state);
  const timer = useRef<ReturnType<typeof setTimeout> | null>(null);
  const sent = useRef<string | null>(null);

  const publish = useEffectEvent(() => {
    timer.current = null;
    if (!bridge) return;
    const values = stateValues(latest.current, latest.current.shell.page);
    const text = JSON.stringify(values);
    if (text === sent.current) return;
    const first = sent.current === null;
    sent.current = text;
    bridge.publish(values, first);
  });

  useEffect(() => {
    latest.current = state;
    if (!bridge || timer.current !== null) return;
    timer.current = setTimeout(publish, STATE_EVENT_INTERVAL_MS);
  }, [bridge, state]);

  useEffect(
    () => () => {
      if (timer.current !== null) clearTimeout(timer.current);
      timer.current = null;
    },
    [],
  );

  const onPatch = useEffectEvent((patch: Record<string, unknown>, source: PatchSource) => {
    const r = applyPatch(latest.current, patch, source === 'parent' ? locked : []);
    for (const x of r.refused) console.warn(`fourbar-lab: ignoring ${x.key} from the ${source}: ${x.why}.`);
    if (r.state === latest.current) return;
    latest.current = r.state; // a second patch before the next render builds on this one
    dispatch({ type: 'replace', state: r.state });
  });

  useEffect(() => (bridge ? bridge.listen(onPatch) : undefined), [bridge]);
}
