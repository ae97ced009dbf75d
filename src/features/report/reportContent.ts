import type { PrintFact } from '../../shared/print/PrintFacts';

/** One labelled value of the report: its label and its text as the panels show it (key: the panel's, e.g. 'theta3'). */
export type ReportFact = PrintFact;

/** One plot of the report: its title and its standalone SVG text (drawn by the chart kit). */
export interface ReportPlot {
  title: string;
  svg: string;
  /** What it plots (a stable key e2e finds it by, e.g. 'torque'); the chosen motion plots have none. */
  kind?: string;
}

/** Everything the printed page shows, already formatted: the app composes it from the simulator and the exports. */
export interface ReportContent {
  /** The report's heading and the subtitle under it (the linkage and the branch). */
  title: string;
  subtitle: string;
  /** The linkage figure as standalone SVG text (the canvas's own drawing), and its caption (the lengths). */
  figureSvg: string;
  figureCaption: string;
  /** Grashof and type facts, the design metrics, and the values at the current θ2. */
  classification: ReportFact[];
  metrics: ReportFact[];
  atTheta2Title: string;
  atTheta2: ReportFact[];
  plots: ReportPlot[];
  /** The input and units (ω2 in its unit, the length unit), and a synthesized design's coupler point, placement, targets. */
  setup: ReportFact[];
  /** With Forces on: the input torque, pin forces and shaking at θ2, the cycle's torque and flywheel; else empty. */
  forces: ReportFact[];
  /** With Forces on: the chosen force plot over the turn (the torque unless the plots card shows another); else null. */
  forcePlot: ReportPlot | null;
}
