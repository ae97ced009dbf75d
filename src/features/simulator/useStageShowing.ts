import { useSyncExternalStore } from 'react';
import type { LiveStage } from '../../shared/linkage/liveStage';

const NEVER = () => () => {};
const HIDDEN = () => false;

/** Whether the live stage's canvas shows (its frames cover the page's canvas); false without a stage. */
export function useStageShowing(stage: LiveStage | null | undefined): boolean {
  return useSyncExternalStore(stage?.subscribe ?? NEVER, stage?.showing ?? HIDDEN);
}
