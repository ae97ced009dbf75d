import type { DesignInfo } from '../features/simulator/useDesignMetrics';
import type { Messages } from '../shared/i18n/messages';
import { assemblesAnywhere } from '../shared/state/animation';

/** Why the exports are off, or null: a linkage that assembles at no input angle has no figure, plot or table. */
export function exportBlocked(design: DesignInfo | null, t: Messages): string | null {
  return design && !assemblesAnywhere(design.range) ? t.cannotAssembleAny : null;
}
