import type { StageFrameHost } from '../../../src/shared/linkage/liveStage';

/**
 * A stage worker's clock and animation frames run by hand (the stage loops' tests): host for the loop, the replies it
 * sent, the frames it asked for (pending), and frameAt(ms), which sets the clock and runs the frames then due.
 */
export function handRunFrames<R>(timeOrigin: number, withFrames = true) {
  let now = 0;
  let nextHandle = 1;
  const pending = new Map<number, (now: number) => void>();
  const replies: R[] = [];
  const host: StageFrameHost<R> = {
    now: () => now,
    timeOrigin,
    requestFrame: withFrames
      ? (callback) => {
          pending.set(nextHandle, callback);
          return nextHandle++;
        }
      : null,
    cancelFrame: (h) => pending.delete(h),
    reply: (m) => replies.push(m),
  };
  const frameAt = (ms: number) => {
    now = ms;
    const due = [...pending.values()];
    pending.clear();
    for (const callback of due) callback(ms);
  };
  return { host, replies, pending, frameAt, now: () => now };
}
