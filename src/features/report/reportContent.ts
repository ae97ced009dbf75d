/** One labelled value of the report: its label and its text as the panels show it. */
export interface ReportFact {
  label: string;
  value: string;
  /** A stable key e2e compares with the panel's own (e.g. 'theta3'). */
  key: string;
  /** Across the facts' two columns. */
  wide?: boolean;
}

/** One plot of the report: its title and its standalone SVG text (drawn by the chart kit). */
export interface ReportPlot {
  title: string;
  svg: string;
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
}
