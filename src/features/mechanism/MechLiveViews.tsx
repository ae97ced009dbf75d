import { useSyncExternalStore } from 'react';
import type { ReactNode } from 'react';
import type { MechanismSpec } from '../../mechanism';
import type { MarkerAt } from '../../shared/charts/chart';
import type { XYChartData } from '../../shared/charts/xyChart';
import { XYChartView } from '../../shared/charts/XYChartView';
import type { MechCanvasProps } from './MechCanvas';
import { MechCanvas } from './MechCanvas';
import type { MechPicture } from './drawMechanism';
import type { PlayheadSource } from './livePlayhead';
import { usePlayheadInput } from './livePlayhead';
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

/**
 * A short fingerprint of a picture's pose (the sum of x + √2·y over its points, 6 digits): tools and the bench see a
 * new pose drawn. The irrational weight keeps a move along a rational slope (a drag 2 px across, 1 px down) from
 * cancelling out.
 */
export function poseDigest(picture: MechPicture): string {
  let sum = 0;
  for (const q of Object.values(picture.pose.joints)) sum += q.x + Math.SQRT2 * q.y;
  for (const q of Object.values(picture.pose.points)) sum += q.x + Math.SQRT2 * q.y;
  return sum.toPrecision(6);
}

/** Props of MechStage: the canvas's props but its picture, which pictureAt makes for the input shown. */
export interface MechStageProps extends Omit<MechCanvasProps, 'picture'> {
  at: PlayheadInput;
  pictureAt: (input: number, dragged: MechanismSpec | null) => MechPicture;
  /** The spec a joint's drag draws now (null: no drag). */
  dragged: DraggedSource;
}

/**
 * The linkage's canvas at the input shown, redrawn every frame of Play and every move of a joint's drag, in a box (no box of its own: display
 * contents) whose data-input is the input drawn and data-pose its poseDigest, for tests and the bench.
 */
export function MechStage({ at, pictureAt, dragged, ...canvas }: MechStageProps) {
  const input = useShownInput(at);
  const picture = pictureAt(input, useSyncExternalStore(dragged.subscribe, dragged.get));
  return (
    <div className="mech-stage" data-input={input} data-pose={poseDigest(picture)}>
      <MechCanvas picture={picture} {...canvas} />
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
