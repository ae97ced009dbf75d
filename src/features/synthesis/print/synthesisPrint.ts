import type { PrintFact } from '../../../shared/print/PrintFacts';
import type { DrawPicture } from '../../../shared/canvas/exportDrawing';
import { drawingSvg } from '../../../shared/canvas/exportDrawing';

/** A printed table: its caption, column heads and rows of texts (each row keyed for e2e, e.g. 'T3'). */
export interface PrintTable {
  caption: string;
  columns: string[];
  rows: { key: string; cells: string[] }[];
}

/** What the synthesis page prints for its mode, already formatted: the task, the chosen design and its figure. */
export interface SynthesisPrintContent {
  /** The heading (the mode in it). */
  title: string;
  /** The task: targets' or poses' count, timing, ranges, bounds, options, seed, length unit. */
  task: PrintFact[];
  /** The chosen design: its lengths with the unit, type, coupler point and placement, its errors; empty without one. */
  design: PrintFact[];
  /** Its defects in words (the panel's "none" when it has none); empty without a design. */
  defects: string[];
  /** The targets or poses with the design's error at each; null when the mode has none. */
  table: PrintTable | null;
  /** The mode's canvas picture (targets, curve, linkage) as standalone SVG text; null without a picture. */
  figureSvg: string | null;
  /** A line under the heading when there is no design yet or it is out of date; else null. */
  note: string | null;
}

/** The figure's drawing size (CSS pixels): the canvas's picture drawn again at this size, as SVG. */
export const PRINT_FIGURE_SIZE = { width: 520, height: 400 } as const;

/** A mode's canvas picture drawn at the print figure's size as SVG text (draw gets the size in CSS pixels). */
export function printFigure(draw: (width: number, height: number) => DrawPicture): string {
  const { width, height } = PRINT_FIGURE_SIZE;
  return drawingSvg(draw(width, height), width, height);
}
