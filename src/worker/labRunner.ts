import { runWorkPrecision } from '../lab/workPrecision';
import type { LabRequest, SolverResponse } from './protocol';

/**
 * Runs a lab request: the work-precision study with progress messages, yielding to the event loop
 * between stages so a cancel message can arrive. The 40-digit reference (decimal.js) is loaded
 * only now, so the simulator never downloads it. Always answers: a result, null when cancelled,
 * or an error response.
 */
export async function runLabRequest(
  req: LabRequest,
  post: (response: SolverResponse) => void,
  isCancelled: () => boolean,
): Promise<void> {
  try {
    const { referencePose } = await import('../lab/reference');
    const result = await runWorkPrecision(req.linkage, {
      branch: req.branch,
      stepDeg: req.stepDeg,
      now: () => performance.now(),
      reference: referencePose,
      onProgress: (fraction, stage) => post({ type: 'lab-progress', id: req.id, fraction, stage }),
      pause: () => new Promise((resolve) => setTimeout(resolve, 0)),
      isCancelled,
    });
    post({ type: 'lab', id: req.id, result });
  } catch (e) {
    post({ type: 'error', id: req.id, requestType: 'lab', message: e instanceof Error ? e.message : String(e) });
  }
}
