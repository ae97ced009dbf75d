import type { Dispatch } from 'react';
import { startTransition, useCallback, useEffect, useLayoutEffect, useRef } from 'react';
import { advanceTheta2, degreesForElapsed, stepTheta2 } from '../../shared/state/animation';
import type { InputRangeDeg } from '../../shared/state/animation';
import type { Action, AppState } from '../../shared/state/appState';
import { normalizeTheta2Deg } from '../../shared/state/appState';
import type { PlayFrame, Playhead } from '../../shared/state/playhead';
import { frameOf, playBase, sameFrame } from '../../shared/state/playhead';
import { useAnimationFrame } from '../../shared/hooks/useAnimationFrame';

/**
 * How often Play commits its frame to the app state at most, ms. Every frame moves the playhead (canvas and plot
 * markers follow it); the panels, the θ2 field, the worker's numbers and the address bar follow the state,
 * five times a second, in a transition that frames may interrupt.
 */
export const PLAY_COMMIT_MS = 200;
/** A slow device commits less often: the gap is at least this many times the last commit's render (ms). */
const COMMIT_SHARE = 8;
/** ...and at most this (ms): the panels still follow Play. */
const PLAY_COMMIT_MAX_MS = 1000;

/**
 * The gap before Play's next commit, ms: PLAY_COMMIT_MS, or longer on a device where rendering the committed state
 * took lastRenderMs, so the commits take at most about 1/COMMIT_SHARE of the time the animation has (at most
 * PLAY_COMMIT_MAX_MS).
 */
export function playCommitGapMs(lastRenderMs: number): number {
  const ms = Number.isFinite(lastRenderMs) && lastRenderMs > 0 ? lastRenderMs : 0;
  return Math.min(PLAY_COMMIT_MAX_MS, Math.max(PLAY_COMMIT_MS, COMMIT_SHARE * ms));
}

/**
 * Plays the input while state.playing (time based: speed in degrees per nominal 60 FPS frame, rocking
 * between limits when the input cannot turn fully) and returns the step handler: +1 one cycle sample
 * forward in the play direction (so clockwise when Clockwise is chosen), -1 one back. Play waits for the
 * first cycle's input range. Each frame moves the playhead (see PLAY_COMMIT_MS); when Play stops, the frame
 * on screen is committed and the playhead handed back to the state.
 */
export function useAnimation(
  state: AppState,
  dispatch: Dispatch<Action>,
  rangeDeg: InputRangeDeg | null,
  playhead: Playhead,
): (sign: 1 | -1) => void {
  // Touched only in the frame callback and effects: the state's frame at the previous tick, the frames
  // committed and not yet seen in the state (oldest first), and when the last commit was.
  const seen = useRef<PlayFrame | null>(null);
  const committed = useRef<PlayFrame[]>([]);
  const lastCommitMs = useRef(0);
  // When the last commit was dispatched and how long it took to render (measured at its layout effect).
  const dispatchedAt = useRef<number | null>(null);
  const renderMs = useRef(0);
  useLayoutEffect(() => {
    if (dispatchedAt.current === null) return;
    renderMs.current = performance.now() - dispatchedAt.current;
    dispatchedAt.current = null;
  }, [state.motion]);
  useAnimationFrame(state.motion.playing, (dt, now) => {
    // A frame can still come between Pause's render and the loop's cancellation: it must not move on.
    if (!rangeDeg || !state.motion.playing) return;
    const own = frameOf(state);
    const i = committed.current.findIndex((c) => sameFrame(c, own));
    const base = playBase(own, seen.current, playhead.get(), committed.current);
    if (i >= 0) committed.current = committed.current.slice(i + 1);
    seen.current = own;
    const next = advanceTheta2(
      base.theta2Deg,
      degreesForElapsed(state.motion.speedDegPerFrame, dt),
      base.direction,
      base.branch,
      rangeDeg,
    );
    playhead.set(next);
    if (now - lastCommitMs.current >= playCommitGapMs(renderMs.current)) {
      lastCommitMs.current = now;
      committed.current = [...committed.current, next];
      dispatchedAt.current = performance.now();
      startTransition(() => dispatch({ type: 'animate', ...next }));
    }
  });
  // Stopped: commit the frame on screen, then (once the state shows it) drop the playhead. An edit that came with
  // the stop (a "Go to" sets θ2 as it stops Play) wins over the frame on screen: the state already holds the pose.
  useEffect(() => {
    if (state.motion.playing) return;
    const own = frameOf(state);
    const edited =
      seen.current !== null && !sameFrame(own, seen.current) && !committed.current.some((c) => sameFrame(c, own));
    seen.current = null;
    committed.current = [];
    const frame = playhead.get();
    if (!frame) return;
    if (edited) {
      playhead.set(null);
      return;
    }
    // Compared as the reducer stores it, so a frame the state cannot hold more exactly still hands back.
    if (sameFrame({ ...frame, theta2Deg: normalizeTheta2Deg(frame.theta2Deg) }, frameOf(state))) playhead.set(null);
    else dispatch({ type: 'animate', ...frame });
  }, [state, playhead, dispatch]);
  return useCallback(
    (sign: 1 | -1) =>
      dispatch({
        type: 'animate',
        ...stepTheta2({ ...frameOf(state), samples: state.solver.samples }, rangeDeg, sign),
      }),
    [state, rangeDeg, dispatch],
  );
}
