import type { Dispatch, RefObject } from 'react';
import { startTransition, useCallback, useEffect, useLayoutEffect, useMemo, useRef, useState } from 'react';
import { flushSync } from 'react-dom';
import { advanceTheta2, degreesForElapsed, stepTheta2 } from '../../shared/state/animation';
import type { InputRangeDeg } from '../../shared/state/animation';
import type { Action, AppState } from '../../shared/state/appState';
import { normalizeTheta2Deg } from '../../shared/state/appState';
import type { PlayFrame, Playhead } from '../../shared/state/playhead';
import { playFrameOf, playBase, sameFrame } from '../../shared/state/playhead';
import { useAnimationFrame } from '../../shared/hooks/useAnimationFrame';
import type { HeldPointers } from '../../shared/hooks/heldPointers';
import { followPointers } from '../../shared/hooks/heldPointers';
import { ExternalValue } from '../../shared/state/externalValue';
import type { LiveStage } from '../../shared/linkage/liveStage';
import { CommitPacer, playCommitGapMs } from './commitPacer';
import { dragViaStage } from './stage/pageDraws';

/**
 * A drag of θ2 with nothing moving it for this long (ms) rests: its value is committed. A drag by no pointer (a script
 * setting the slider's value) then ends; one whose pointer is still down goes on (on a slow page a student's moves can
 * be this far apart), and ends at the pointer's release.
 */
export const SCRUB_REST_MS = 300;

/**
 * A drag of θ2 (the slider, the crank pin on the canvas) moves the playhead, as Play does: the canvas and the plot
 * markers follow every value, the app state (panels, worker numbers, address bar) follows in transitions at most
 * every playCommitGapMs, and the drag's last value is committed when it ends.
 */
export interface Theta2Scrub {
  /** Shows θ2 = deg (degrees) at once. stopPlay: taking hold of the crank stops Play; otherwise Play goes on from deg. */
  move(deg: number, stopPlay?: boolean): void;
  /** The drag ended (released): commits the value on screen and hands the pose back to the state. */
  end(): void;
  /** The value being dragged (degrees), null between drags: the θ2 slider and field show it (useSyncExternalStore). */
  dragged(): number | null;
  /** Adds a listener to changes of dragged(); returns its removal. */
  subscribe(listener: () => void): () => void;
}

/** What useAnimation gives: one sample forward or back, and the θ2 drag. */
export interface AnimationHandlers {
  step: (sign: 1 | -1) => void;
  scrub: Theta2Scrub;
}

/**
 * Plays the input while state.playing (time based: speed in degrees per nominal 60 FPS frame, rocking
 * between limits when the input cannot turn fully) and returns the step handler: +1 one cycle sample
 * forward in the play direction (so clockwise when Clockwise is chosen), -1 one back. Play waits for the
 * first cycle's input range. Each frame moves the playhead (see commitPacer.ts); when Play stops, the frame
 * on screen is committed and the playhead handed back to the state. A θ2 drag (Theta2Scrub) moves the same playhead.
 * With a live stage (LiveStage: Play drawn in a worker with its own clock) the playhead follows the stage's newest
 * frame; the page advances it itself only until the stage has drawn one, and restarts the stage from any frame
 * someone else put on the playhead or in the state (an edit, a drag), or at a new speed.
 */
export function useAnimation(
  state: AppState,
  dispatch: Dispatch<Action>,
  rangeDeg: InputRangeDeg | null,
  playhead: Playhead,
  stage: LiveStage | null = null,
): AnimationHandlers {
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
  // The gap before the next commit: playCommitGapMs of the last render, longer while Play's frames are dropped.
  const [pacer] = useState(() => new CommitPacer());
  const gapMs = useRef(playCommitGapMs(0));
  // Commits a frame in a transition when the last commit is at least that gap ago (Play and drags).
  const commitThrottled = (now: number, action: Action): boolean => {
    if (now - lastCommitMs.current < gapMs.current) return false;
    lastCommitMs.current = now;
    dispatchedAt.current = performance.now();
    gapMs.current = pacer.nextGap(renderMs.current);
    startTransition(() => dispatch(action));
    return true;
  };
  const dragging = useRef(false);
  const scrub = useTheta2Scrub(state, dispatch, playhead, commitThrottled, dragging, stage);
  // The frame this loop last put on the playhead, and what the stage was started with (null: not started).
  const lastSet = useRef<PlayFrame | null>(null);
  const stageRun = useRef<{ speed: number; range: InputRangeDeg } | null>(null);
  const lastFrameAt = useRef<number | null>(null);
  useAnimationFrame(state.motion.playing, (dt, now) => {
    // A frame can still come between Pause's render and the loop's cancellation: it must not move on.
    if (!rangeDeg || !state.motion.playing) return;
    if (lastFrameAt.current !== null) pacer.noteFrame(now - lastFrameAt.current);
    lastFrameAt.current = now;
    const own = playFrameOf(state);
    const i = committed.current.findIndex((c) => sameFrame(c, own));
    const base = playBase(own, seen.current, playhead.get(), committed.current);
    if (i >= 0) committed.current = committed.current.slice(i + 1);
    seen.current = own;
    const speed = state.motion.speedDegPerFrame;
    const advanced = advanceTheta2(base.theta2Deg, degreesForElapsed(speed, dt), base.direction, base.branch, rangeDeg);
    let next = advanced;
    if (stage) {
      const run = stageRun.current;
      const moved = lastSet.current !== null && !sameFrame(base, lastSet.current);
      if (!run || moved || run.speed !== speed || run.range !== rangeDeg) {
        stage.play(advanced, now, speed, rangeDeg);
        stageRun.current = { speed, range: rangeDeg };
      } else next = stage.latest() ?? advanced;
    }
    playhead.set(next);
    lastSet.current = next;
    if (commitThrottled(now, { type: 'animate', ...next })) committed.current = [...committed.current, next];
  });
  // Stopped: commit the frame on screen, then (once the state shows it) drop the playhead. An edit that came with
  // the stop (a "Go to" sets θ2 as it stops Play) wins over the frame on screen: the state already holds the pose.
  useEffect(() => {
    if (state.motion.playing) return;
    pacer.reset();
    lastFrameAt.current = null;
    gapMs.current = playCommitGapMs(renderMs.current);
    // The stage's newest frame is the one on screen: it is the one Pause keeps. A drag that stopped Play goes on
    // showing its frames on the stage (the drag's end stops it).
    const drawn = stageRun.current ? stage?.latest() : null;
    if (drawn && !dragging.current) playhead.set(drawn);
    stageRun.current = null;
    lastSet.current = null;
    if (dragging.current) return;
    stage?.stop();
    const own = playFrameOf(state);
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
    if (sameFrame({ ...frame, theta2Deg: normalizeTheta2Deg(frame.theta2Deg) }, playFrameOf(state))) playhead.set(null);
    else dispatch({ type: 'animate', ...frame });
  }, [state, playhead, dispatch, stage, pacer]);
  const step = useCallback(
    (sign: 1 | -1) =>
      dispatch({
        type: 'animate',
        ...stepTheta2({ ...playFrameOf(state), samples: state.solver.samples }, rangeDeg, sign),
      }),
    [state, rangeDeg, dispatch],
  );
  return useMemo(() => ({ step, scrub }), [step, scrub]);
}

/**
 * The θ2 drag of useAnimation: moves the playhead, commits through commit (throttled, returns whether it
 * dispatched) and, once the drag rests for SCRUB_REST_MS or end() is called, commits the last value at once.
 * draggingRef is true from the first move to the end: Play's stop effect leaves the playhead alone meanwhile. With a
 * live stage the dragged frames are drawn there (the page's canvas then redraws only as the state commits); the end
 * hands the canvas back in the commit of the last value.
 */
function useTheta2Scrub(
  state: AppState,
  dispatch: Dispatch<Action>,
  playhead: Playhead,
  commit: (now: number, action: Action) => boolean,
  draggingRef: RefObject<boolean>,
  stage: LiveStage | null,
): Theta2Scrub {
  const latest = useRef({ state, commit });
  useLayoutEffect(() => {
    latest.current = { state, commit };
  });
  const restTimer = useRef<ReturnType<typeof setTimeout> | undefined>(undefined);
  const viaStage = useRef(false);
  useEffect(() => () => clearTimeout(restTimer.current), []);
  const [dragged] = useState(() => new ExternalValue<number | null>(null));
  const pointer = useRef<HeldPointers | null>(null);
  const handlers = useMemo<Theta2Scrub>(() => {
    const end = () => {
      clearTimeout(restTimer.current);
      const committing = draggingRef.current;
      draggingRef.current = false;
      const frame = playhead.get();
      if (!committing || !frame || latest.current.state.motion.playing) {
        dragged.set(null);
        if (!latest.current.state.motion.playing) stage?.stop();
        return;
      }
      // One synchronous commit of the last value (the slider goes back to the state, which now holds it); the
      // stop effect then hands the pose back to the state.
      flushSync(() => {
        dispatch({ type: 'setTheta2', deg: frame.theta2Deg });
        dragged.set(null);
        stage?.stop();
      });
      const shown = { ...frame, theta2Deg: normalizeTheta2Deg(frame.theta2Deg) };
      if (playhead.get() === frame && sameFrame(shown, playFrameOf(latest.current.state))) playhead.set(null);
    };
    /** The drag rested: a held pointer's drag commits its value and goes on; any other ends. */
    const rest = () => {
      const frame = playhead.get();
      if (!pointer.current?.held() || !draggingRef.current || !frame) return end();
      dispatch({ type: 'setTheta2', deg: frame.theta2Deg });
    };
    const move = (deg: number, stopPlay = false) => {
      const { state: s, commit: commitNow } = latest.current;
      const next = { ...(playhead.get() ?? playFrameOf(s)), theta2Deg: normalizeTheta2Deg(deg) };
      if (stopPlay && s.motion.playing) dispatch({ type: 'setPlaying', playing: false });
      playhead.set(next);
      dragged.set(next.theta2Deg);
      clearTimeout(restTimer.current);
      restTimer.current = setTimeout(rest, SCRUB_REST_MS);
      // While Play runs it goes on from here and commits itself.
      if (s.motion.playing && !stopPlay) return;
      // The drag's frames go to the stage where the page draws slowly (dragViaStage).
      const first = !draggingRef.current;
      viaStage.current = dragViaStage(first, viaStage.current, stage?.prefersStage() ?? false);
      if (first && !viaStage.current) stage?.warm();
      draggingRef.current = true;
      if (viaStage.current) stage?.show(next);
      commitNow(performance.now(), { type: 'setTheta2', deg: next.theta2Deg });
    };
    return { move, end, dragged: dragged.get, subscribe: dragged.subscribe };
  }, [playhead, dispatch, draggingRef, dragged, stage]);
  // A release ends a drag that rested while the pointer was down (the slider's change event may not come after it).
  useEffect(() => {
    const followed = followPointers({
      release: () => {
        if (draggingRef.current) handlers.end();
      },
    });
    pointer.current = followed;
    return () => {
      followed.dispose();
      pointer.current = null;
    };
  }, [handlers, draggingRef]);
  return handlers;
}
