import { useEffect, useMemo, useSyncExternalStore } from 'react';
import type { ReactNode } from 'react';
import type { MarkerAt } from '../../shared/charts/chart';
import type { XYChartData } from '../../shared/charts/xyChart';
import { XYChartView } from '../../shared/charts/XYChartView';
import type { MechCanvasProps } from './MechCanvas';
import { MechCanvas } from './MechCanvas';
import type { MechScene } from './mechScene';
import { mechPictureAt, poseDigest } from './mechScene';
import type { PlayheadSource } from './livePlayhead';
import { throttledSubscribe, usePlayheadInput } from './livePlayhead';
import type { DraggedSource } from './useJointDrag';

/**
 * The page's views that follow Play (the canvas, the plots' markers, the readouts): each reads the playhead from the
 * page's PlayheadSource, so a frame of Play re-renders these few views and not the page. Numbers people read (the
 * input's readout and slider, the positions, the forces' values) follow at READOUT_MS, as on the simulator.
 */

/** How often a text readout follows Play (ms): five times a second. */
export const READOUT_MS = 200;

/** Where a view reads the input: the playhead (while Play runs), the committed input, and the run's clamp. */
export interface PlayheadInput {
  playhead: PlayheadSource;
  /** The committed input (rad or length). */
  rest: number;
  /** Keeps an input within the run Play moves over. */
  clamp: (input: number) => number;
}

/** The input a view shows (clamped to the run), every frame of Play or at most every `everyMs` ms. */
function useShownInput({ playhead, rest, clamp }: PlayheadInput, everyMs?: number): number {
  return clamp(usePlayheadInput(playhead, rest, everyMs));
}

/** Props of MechStage: the canvas's props but its picture, which is the scene's at the input shown. */
export interface MechStageProps extends Omit<MechCanvasProps, 'picture' | 'hold'> {
  at: PlayheadInput;
  scene: MechScene;
  /** The spec a joint's drag draws now (null: no drag). */
  dragged: DraggedSource;
}

/** The subscription of a page without a live stage: its canvas never hides under one. */
const still = () => () => {};

/**
 * The linkage's canvas at the input shown, in a box (no box of its own: display contents) whose data-input is the input
 * shown and data-pose its poseDigest, for tests and the bench. The page draws every frame of Play and every move of a
 * joint's drag itself, unless a live stage (its worker) does: each move of a drag goes to the stage, as do the scene
 * and the view, and while the stage's canvas shows, this one keeps what it drew and follows (its data attributes) at
 * READOUT_MS; it draws the state on screen again in the commit that hides the stage's canvas.
 */
export function MechStage({ at, scene, dragged, live = null, ...canvas }: MechStageProps) {
  const showing = useSyncExternalStore(live?.subscribe ?? still, () => live?.showing() ?? false);
  const input = useShownInput(at, showing ? READOUT_MS : undefined);
  const draggedSubscribe = useMemo(
    () => (showing ? throttledSubscribe(dragged.subscribe, READOUT_MS) : dragged.subscribe),
    [showing, dragged],
  );
  const spec = useSyncExternalStore(draggedSubscribe, dragged.get);
  const picture = mechPictureAt(scene, input, spec);
  useEffect(() => {
    live?.setScene(scene);
  }, [live, scene]);
  // A run of the stage ends with this view (a new template remounts it, with a new canvas for the stage).
  useEffect(() => () => live?.stop(), [live]);
  // Each move of a drag is drawn by the stage; its end stops it (the page draws the committed linkage).
  useEffect(() => {
    if (!live) return;
    return dragged.subscribe(() => {
      const next = dragged.get();
      if (!live.usable()) return;
      if (next) live.show(0, next);
      else live.stop();
    });
  }, [live, dragged]);
  return (
    <div className="mech-stage" data-input={input} data-pose={poseDigest(picture)}>
      <MechCanvas picture={picture} live={live} hold={showing} {...canvas} />
    </div>
  );
}

/** Props of MechPlotCell: one plot's data and texts, its marker at an input, and a note under it. */
export interface MechPlotCellProps {
  at: PlayheadInput;
  data: XYChartData;
  texts: { title: string; xLabel: string; yLabel: string };
  markerAt: (input: number) => MarkerAt | null;
  testId: string;
  note: ReactNode;
}

/** One of the page's plots: the chart is drawn when its data change; Play moves only its marker. */
export function MechPlotCell({ at, data, texts, markerAt, testId, note }: MechPlotCellProps) {
  const input = useShownInput(at);
  return (
    <div className="mech-chart-cell">
      <XYChartView className="mech-chart" data={data} marker={markerAt(input)} texts={texts} testId={testId} />
      {note}
    </div>
  );
}

/** Renders children(input) with the input shown, following Play at most every READOUT_MS ms (or every frame). */
export function AtPlayhead({
  at,
  everyFrame = false,
  children,
}: {
  at: PlayheadInput;
  /** Follow every frame (a view with a marker), not at READOUT_MS; default false. */
  everyFrame?: boolean;
  children: (input: number) => ReactNode;
}) {
  return children(useShownInput(at, everyFrame ? undefined : READOUT_MS));
}
