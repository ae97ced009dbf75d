import { radToDeg } from '../../../solver/angles';
import { formatNumber } from '../../../shared/format';
import type { SynPathState } from '../../../shared/state/appState';
import type { SynthesisMessages } from '../synthesisMessages';
import type { PathTaskReason } from './pathTaskChecks';
import { missingTheta2, noneClose, pathTaskReasons } from './pathTaskChecks';
import { targetsExtent } from './pathTaskOf';
import type { PathRunState } from './usePathSynthesis';

/** A reason a task cannot be met, in words. */
function reasonText(r: PathTaskReason, st: SynthesisMessages): string {
  const n = (x: number) => formatNumber(x, 4);
  switch (r.kind) {
    case 'span':
      return st.reasonSpan(n(r.reach), n(r.span));
    case 'pivot-far':
      return st.reasonPivotFar(st.targetName(r.target), n(r.distance), n(r.reach));
    case 'same-theta2':
      return st.reasonSameTheta2(st.targetName(r.a), st.targetName(r.b), formatNumber(radToDeg(r.theta2), 6));
  }
}

/** Why Synthesize waits: fields in error (by name), or a target without its given θ2; null when it may run. */
export function holdText(
  fieldErrors: ReadonlyMap<string, string>,
  s: SynPathState,
  st: SynthesisMessages,
): string | null {
  if (fieldErrors.size > 0) return st.fieldsInError([...fieldErrors.keys()].join(', '));
  const missing = missingTheta2(s);
  return missing === null ? null : st.missingTheta2(st.targetName(missing));
}

/**
 * The summary under a finished, current run none of whose answers passes close to every target: the targets' size
 * and why the task cannot be met (where known); null otherwise.
 */
export function noFitSummary(run: PathRunState, stale: boolean, st: SynthesisMessages): string | null {
  const finished = run.status === 'done' || run.status === 'stopped';
  if (!finished || stale || !run.task || !run.solutions || !noneClose(run.task, run.solutions)) return null;
  const why = pathTaskReasons(run.task).map((r) => reasonText(r, st));
  const size = formatNumber(targetsExtent(run.task.targets).size, 4);
  return [st.noFit(size), ...(why.length > 0 ? why : [st.reasonUnknown])].join(' ');
}
