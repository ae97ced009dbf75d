import { scaleLog } from 'd3-scale';
import { symbol, symbolCircle, symbolDiamond } from 'd3-shape';
import type { LabPoint, LabSeries } from '../../study/workPrecision';
import type { SweepMethod } from '../../solver/types';
import { CHART_COLORS } from '../../shared/theme/tokens';
import { formatSci } from '../../shared/format';
import type {
  ChartScales,
  ChartSizeOptions,
  ChartSpec,
  ChartTexts,
  Curve,
  GSel,
  PlotArea,
} from '../../shared/charts/chart';
import type { LegendItem } from '../../shared/charts/chartFrame';
import { CHART_STYLE, child, estimateTextWidth, minus } from '../../shared/charts/chartFrame';
import type { ChartDrawing } from '../../shared/charts/exportChart';
import { specDrawing } from '../../shared/charts/exportChart';
import { dec, logTicks, niceLogDomain, niceOneTwoFiveDomain } from '../../shared/charts/ticks';
import { placeLabels as placeBoxes } from '../../shared/canvas/labelPlacement';

/**
 * The lab's work-precision diagram as a chart-kit spec: median time per point (ns, log x) against max angle error
 * (rad, log y, floored at ERROR_FLOOR), a line per traced method over its tolerances, a diamond per default, red
 * outlines for trouble, the chosen point ringed and tolerance labels placed clear of the marks.
 */

/** Fixed colour of each lab method, so a method looks the same in every chart and table. */
export const METHOD_COLORS: Readonly<Record<SweepMethod, string>> = {
  'closed-form': CHART_COLORS.methodClosedForm,
  'closed-form-polish': CHART_COLORS.methodClosedFormPolish,
  newton: CHART_COLORS.methodNewton,
  'newton-no-predictor': CHART_COLORS.methodNewtonNoPredictor,
  seed: CHART_COLORS.methodSeed,
};

/** Outline of a marker whose configuration failed, jumped branch or falsely converged somewhere on the cycle. */
export const FAILURE_COLOR: string = CHART_COLORS.failure;

/** Errors below this (rad), exact zeros included, are drawn at this floor of the log scale. */
export const ERROR_FLOOR = 1e-17;

/** Which point the user chose: a method and its tolerance (null: the method's default). */
export interface WorkPrecisionHighlight {
  method: SweepMethod;
  tol: number | null;
}

/** Data of the work-precision diagram: the lab's series and the chosen point (ringed; none by default). */
export interface WorkPrecisionData {
  series: readonly LabSeries[];
  highlight?: WorkPrecisionHighlight | null;
}

/** Texts of the work-precision diagram. */
export interface WorkPrecisionText extends ChartTexts {
  /** Text shown in the middle when there is no point to plot; default none. */
  emptyText?: string;
}

/** How the diagram words and labels its marks (read once, when its spec is made). */
export interface WorkPrecisionSpecOptions {
  /** Small tolerance labels ('1e-6') beside the traced points; default true. */
  tolLabels?: boolean;
  /** Legend and tooltip label per method; default each series' own label. */
  methodLabels?: Partial<Record<SweepMethod, string>>;
  /** Text for the default tolerance in tooltips; default 'default'. */
  defaultTolText?: string;
  /** Extra legend entry explaining the diamond (default settings); omitted when not given. */
  defaultLegend?: string;
  /** Extra legend entry explaining the red outline (failures, wrong branch, false convergence); omitted when not given. */
  failureLegend?: string;
  /** Tooltip text of one marker; default label, tolerance, ns/pt and max error on separate lines. */
  tooltip?: (series: LabSeries, point: LabPoint) => string;
}

/** Everything the diagram shows but its size and series: texts, wording and the chosen point. */
export interface WorkPrecisionChartOptions extends WorkPrecisionText, WorkPrecisionSpecOptions {
  /** The chosen method and tolerance, drawn with an orange ring; none by default. */
  highlight?: WorkPrecisionHighlight | null;
}

/** Size options of the diagram: its margins (the legend's rows push the plot down) and tick spacing, CSS pixels. */
export const WORK_PRECISION_SIZE: Omit<ChartSizeOptions, 'width' | 'height'> = {
  margins: { top: 55, right: 16, bottom: 40, left: 66 },
  xTickSpacing: 60,
  xMaxTicks: Infinity,
  yTickSpacing: 24,
};

/**
 * Formats a tolerance for labels and CSV: 'default' (or defaultText) for null, otherwise the shortest
 * exponent form with an ASCII minus, e.g. 1e-6 -> '1e-6', 2.5e-9 -> '2.5e-9'.
 */
export function formatTol(tol: number | null, defaultText = 'default'): string {
  if (tol === null) return defaultText;
  if (!Number.isFinite(tol)) return String(tol);
  return tol.toExponential().replace('e+', 'e');
}

/** A tolerance as shown on the page (table, choices, tooltips, stage): formatTol with U+2212, as formatSci writes. */
export function shownTol(tol: number | null, defaultText = 'default'): string {
  return minus(formatTol(tol, defaultText));
}

/** A max error for the lab's table and tooltips: two significant digits, a dash when it is not finite. */
export function formatMaxError(x: number): string {
  return Number.isFinite(x) ? formatSci(x, 2) : '—';
}

/** The y value a max error is drawn at (rad): NaN stays NaN (not drawn), anything below ERROR_FLOOR sits on it. */
export function plottedError(maxError: number): number {
  if (Number.isNaN(maxError)) return NaN;
  return maxError < ERROR_FLOOR ? ERROR_FLOOR : maxError;
}

/** True when a point can be drawn: a finite positive time and a max error that is not NaN. */
export function isDrawable(p: LabPoint): boolean {
  return (
    Number.isFinite(p.nsPerPoint) &&
    p.nsPerPoint > 0 &&
    !Number.isNaN(p.maxError) &&
    Number.isFinite(plottedError(p.maxError))
  );
}

/** True when the configuration went wrong somewhere on the cycle (failed, wrong branch or false convergence). */
export function hasTrouble(p: LabPoint): boolean {
  return p.failures > 0 || p.wrongBranch > 0 || p.falseConvergence > 0;
}

/** One method's curve split for drawing: traced points loosest tolerance first (NaN ones kept, as gaps) and its default point. */
export interface CurvePoints {
  traced: LabPoint[];
  /** The tol === null point, or null when the method has none or it cannot be drawn. */
  defaultPoint: LabPoint | null;
}

/**
 * Orders a method's points for its curve: the points with a tolerance sorted by tolerance descending
 * (loosest first; ties keep their order), and the default point apart (it is not joined).
 */
export function orderedCurvePoints(series: LabSeries): CurvePoints {
  const traced = series.points.filter((p) => p.tol !== null).sort((a, b) => (b.tol as number) - (a.tol as number));
  const d = series.points.find((p) => p.tol === null);
  return { traced, defaultPoint: d && isDrawable(d) ? d : null };
}

/**
 * Log-scale domains of the diagram from the drawable points: x (ns per point) padded by 15 % and
 * widened to 1-2-5 bounds (niceOneTwoFiveDomain), at least a decade; y (rad, floored at ERROR_FLOOR)
 * padded by a quarter decade and widened to whole decades by d3's nice, at least two decades.
 * Without points: x [10, 10000], y [1e-17, 1].
 */
export function workPrecisionDomains(series: readonly LabSeries[]): { x: [number, number]; y: [number, number] } {
  let x0 = Infinity;
  let x1 = 0;
  let y0 = Infinity;
  let y1 = 0;
  for (const s of series) {
    for (const p of s.points) {
      if (!isDrawable(p)) continue;
      const e = plottedError(p.maxError);
      x0 = Math.min(x0, p.nsPerPoint);
      x1 = Math.max(x1, p.nsPerPoint);
      y0 = Math.min(y0, e);
      y1 = Math.max(y1, e);
    }
  }
  if (!(x1 > 0)) return { x: [10, 10000], y: [ERROR_FLOOR, 1] };
  let [xlo, xhi] = niceOneTwoFiveDomain(x0 / 1.15, x1 * 1.15);
  if (xhi / xlo < 10) {
    // Less than a decade of spread: centre a full decade on the data so the axis has ticks to read.
    const mid = Math.sqrt(x0 * x1);
    [xlo, xhi] = niceOneTwoFiveDomain(mid / Math.sqrt(10), mid * Math.sqrt(10));
  }
  const quarterDecade = 10 ** 0.25;
  const [ylo, yhiNice] = niceLogDomain(y0 / quarterDecade, y1 * quarterDecade);
  const yhi = yhiNice / ylo < 100 ? dec(1, Math.round(Math.log10(ylo)) + 2) : yhiNice;
  return { x: [xlo, xhi], y: [ylo, yhi] };
}

/** Formats a positive time tick (ns): plain digits from 0.01 to 99999, otherwise like formatTol ('1e6'). */
export function formatTimeTick(v: number): string {
  if (v >= 0.01 && v < 1e5) return String(Number(v.toPrecision(3)));
  return formatErrorTick(v);
}

/** Formats a positive error tick (rad) in exponent form with a typographic minus: 1e-16 -> '1e−16', 5e-3 -> '5e−3'. */
export function formatErrorTick(v: number): string {
  return minus(formatTol(Number(v.toPrecision(3))));
}

/** A text label's box in plot pixels. */
export interface LabelBox {
  x0: number;
  y0: number;
  x1: number;
  y1: number;
}

/** A placed label: anchor point of the text (baseline) and its text-anchor. */
export interface PlacedLabel {
  x: number;
  y: number;
  anchor: 'start' | 'middle' | 'end';
}

/** Air around each label box (px), so neighbours never read as one word. */
const LABEL_AIR = 3;

/**
 * Greedy label placement on the app's one placer (shared/canvas/labelPlacement): for each point (x, y) with a
 * label of width w and font size h, tries right, left, above, below, then the four diagonals, gap pixels away
 * (per item, else defaultGap), and keeps the first spot inside [0, width] x [0, height] whose box (with
 * LABEL_AIR around it) overlaps neither an obstacle nor an earlier label; null when every spot is taken.
 */
export function placePointLabels(
  items: ReadonlyArray<{ x: number; y: number; w: number; h: number; gap?: number }>,
  obstacles: readonly LabelBox[],
  width: number,
  height: number,
  defaultGap = 7,
): Array<PlacedLabel | null> {
  // A label's padded box is centred on its request's candidate; the text must lie inside the plot, so the
  // bounds grow by the padding (LABEL_AIR across, 1 px down and up).
  const bounds = { x: -LABEL_AIR, y: -1, width: width + 2 * LABEL_AIR, height: height + 2 };
  const exclusions = obstacles.map((o) => ({ x: o.x0, y: o.y0, width: o.x1 - o.x0, height: o.y1 - o.y0 }));
  const spotsOf = items.map(({ x, y, w, h, gap = defaultGap }) => {
    const asc = 0.75 * h;
    const desc = 0.25 * h;
    const spots: PlacedLabel[] = [
      { x: x + gap, y: y + asc / 2, anchor: 'start' },
      { x: x - gap, y: y + asc / 2, anchor: 'end' },
      { x, y: y - gap - desc, anchor: 'middle' },
      { x, y: y + gap + asc, anchor: 'middle' },
      { x: x + gap * 0.7, y: y - gap * 0.7, anchor: 'start' },
      { x: x + gap * 0.7, y: y + gap * 0.7 + asc, anchor: 'start' },
      { x: x - gap * 0.7, y: y - gap * 0.7, anchor: 'end' },
      { x: x - gap * 0.7, y: y + gap * 0.7 + asc, anchor: 'end' },
    ];
    const centres = spots.map((s) => {
      const left = s.anchor === 'start' ? s.x : s.anchor === 'end' ? s.x - w : s.x - w / 2;
      return { x: left + w / 2, y: s.y + (desc - asc) / 2 };
    });
    return { spots, centres, width: w + 2 * LABEL_AIR, height: asc + desc + 2 };
  });
  const requests = spotsOf.map((r, i) => ({ id: String(i), width: r.width, height: r.height, candidates: r.centres }));
  const { placed } = placeBoxes(requests, bounds, exclusions, []);
  const spot = new Map(placed.map((p) => [Number(p.id), spotsOf[Number(p.id)].spots[p.candidateIndex]]));
  return items.map((_, i) => spot.get(i) ?? null);
}

/** One drawn marker, in plot pixels (internal). */
interface Marker {
  series: LabSeries;
  point: LabPoint;
  isDefault: boolean;
  color: string;
  x: number;
  y: number;
}

function defaultTooltip(label: string, p: LabPoint, defaultTolText: string): string {
  const err = p.maxError === 0 ? '0' : minus(p.maxError.toExponential(2));
  return `${label}\ntol ${shownTol(p.tol, defaultTolText)}\n${p.nsPerPoint.toFixed(0)} ns/pt\nmax error ${err} rad`;
}

/** A method's curve split for drawing (orderedCurvePoints) with its series. */
type MethodCurve = { sr: LabSeries } & CurvePoints;

/** The colour of a method. */
const colorOf = (sr: LabSeries) => METHOD_COLORS[sr.method] ?? CHART_STYLE.muted;

/** True when some drawable point's error is below ERROR_FLOOR (it is drawn on the floor). */
function anyFloored(series: readonly LabSeries[]): boolean {
  return series.some((sr) => sr.points.some((p) => isDrawable(p) && p.maxError < ERROR_FLOOR));
}

/** The diagram's frame: log x and y over workPrecisionDomains, log ticks (anchored on the floor when it is used). */
export function workPrecisionFrame(data: WorkPrecisionData, plot: PlotArea): Omit<ChartScales, 'iw' | 'ih'> {
  const dom = workPrecisionDomains(data.series);
  const floored = anyFloored(data.series);
  return {
    x: scaleLog().domain(dom.x).range([0, plot.iw]),
    y: scaleLog().domain(dom.y).range([plot.ih, 0]),
    xTicks: logTicks(dom.x, plot.xCount),
    yTicks: logTicks(dom.y, plot.yCount, floored ? Math.round(Math.log10(ERROR_FLOOR)) : 0),
    yFloor: floored ? ERROR_FLOOR : undefined,
  };
}

/** Each traced method as a line over its tolerances, loosest first; a point that cannot be drawn is a gap. */
function methodCurves(data: WorkPrecisionData, labelOf: (sr: LabSeries) => string): Curve[] {
  return data.series
    .map((sr): MethodCurve => ({ sr, ...orderedCurvePoints(sr) }))
    .filter((c) => c.traced.length > 0)
    .map((c) => ({
      label: labelOf(c.sr),
      color: colorOf(c.sr),
      x: c.traced.map((p) => (isDrawable(p) ? p.nsPerPoint : NaN)),
      y: c.traced.map((p) => (isDrawable(p) ? p.maxError : NaN)),
      strokeWidth: 1.6,
    }));
}

/** The legend: each method (a line through a dot when traced, a diamond for a default alone), then the keys that apply. */
function methodLegend(data: WorkPrecisionData, o: WorkPrecisionSpecOptions, labelOf: (sr: LabSeries) => string) {
  const curves: MethodCurve[] = data.series.map((sr) => ({ sr, ...orderedCurvePoints(sr) }));
  const items: LegendItem[] = curves.map((c) => ({
    label: labelOf(c.sr),
    color: colorOf(c.sr),
    symbol: c.traced.length > 0 ? 'line-dot' : 'diamond',
  }));
  if (o.defaultLegend && curves.some((c) => c.traced.length > 0 && c.defaultPoint)) {
    items.push({ label: o.defaultLegend, color: CHART_STYLE.muted, symbol: 'hollow-diamond' });
  }
  if (o.failureLegend && data.series.some((sr) => sr.points.some((p) => isDrawable(p) && hasTrouble(p)))) {
    items.push({ label: o.failureLegend, color: FAILURE_COLOR, symbol: 'ring' });
  }
  return items;
}

/** The markers of every method in plot pixels: its drawable traced points, then its default. */
function curveMarkers(series: readonly LabSeries[], frame: ChartScales): Marker[] {
  const markers: Marker[] = [];
  const at = (sr: LabSeries, point: LabPoint, isDefault: boolean): Marker => ({
    series: sr,
    point,
    isDefault,
    color: colorOf(sr),
    x: frame.x(point.nsPerPoint),
    y: frame.y(plottedError(point.maxError)),
  });
  for (const sr of series) {
    const c = orderedCurvePoints(sr);
    for (const p of c.traced) if (isDrawable(p)) markers.push(at(sr, p, false));
    if (c.defaultPoint) markers.push(at(sr, c.defaultPoint, true));
  }
  return markers;
}

/** Draws the markers (dots, default diamonds, red outlines for trouble) with their tooltips. */
function drawMarkers(g: GSel, markers: readonly Marker[], tip: (mk: Marker) => string): void {
  // Defaults first so the smaller traced dots stay visible on top of a diamond they coincide with.
  const ordered = [...markers.filter((mk) => mk.isDefault), ...markers.filter((mk) => !mk.isDefault)];
  const marks = child(g, 'g', 'markers')
    .selectAll<SVGPathElement, Marker>('path')
    .data(ordered)
    .join((enter) => {
      const p = enter.append('path');
      p.append('title');
      return p;
    })
    .attr('transform', (mk) => `translate(${mk.x},${mk.y})`)
    .attr('data-method', (mk) => mk.series.method)
    .attr('data-tol', (mk) => formatTol(mk.point.tol))
    .attr('d', (mk) => (mk.isDefault ? symbol(symbolDiamond, 110)() : symbol(symbolCircle, 34)()) ?? '')
    .attr('fill', (mk) => mk.color)
    .attr('stroke', (mk) => (hasTrouble(mk.point) ? FAILURE_COLOR : CHART_STYLE.background))
    .attr('stroke-width', (mk) => (hasTrouble(mk.point) ? 2 : 1));
  marks.select('title').text(tip);
}

/** Rings the chosen markers. */
function drawHighlight(g: GSel, chosen: readonly Marker[]): void {
  child(g, 'g', 'highlight')
    .selectAll<SVGCircleElement, Marker>('circle')
    .data(chosen)
    .join('circle')
    .attr('cx', (mk) => mk.x)
    .attr('cy', (mk) => mk.y)
    .attr('r', (mk) => (mk.isDefault ? 10 : 8))
    .attr('fill', 'none')
    .attr('stroke', CHART_STYLE.marker)
    .attr('stroke-width', 2)
    .attr('pointer-events', 'none');
}

/** Labels traced markers with their tolerance where placePointLabels finds room, the chosen ones first. */
function drawTolLabels(g: GSel, markers: readonly Marker[], chosen: readonly Marker[], iw: number, ih: number): void {
  const labelSize = 9.5;
  // The chosen point is labelled first so it is never the one crowded out.
  const labelled = [
    ...chosen.filter((mk) => !mk.isDefault),
    ...markers.filter((mk) => !mk.isDefault && !chosen.includes(mk)),
  ];
  const texts = labelled.map((mk) => shownTol(mk.point.tol));
  const obstacles: LabelBox[] = markers.map((mk) => {
    const r = chosen.includes(mk) ? 11 : mk.isDefault ? 7 : 4;
    return { x0: mk.x - r, y0: mk.y - r, x1: mk.x + r, y1: mk.y + r };
  });
  const spots = placePointLabels(
    labelled.map((mk, i) => ({
      x: mk.x,
      y: mk.y,
      w: 1.25 * estimateTextWidth(texts[i], labelSize), // the estimate runs about 20 % short for digits and '−'
      h: labelSize,
      gap: chosen.includes(mk) ? 14 : 7, // clear of the marker (r 4) or the highlight ring (r 11), plus the 3 px of air
    })),
    obstacles,
    iw,
    ih,
  );
  const labels = labelled
    .map((mk, i) => ({ mk, text: texts[i], spot: spots[i] }))
    .filter((l): l is { mk: Marker; text: string; spot: PlacedLabel } => l.spot !== null);
  child(g, 'g', 'tol-labels')
    .selectAll<SVGTextElement, (typeof labels)[number]>('text')
    .data(labels)
    .join('text')
    .attr('x', (l) => l.spot.x)
    .attr('y', (l) => l.spot.y)
    .attr('text-anchor', (l) => l.spot.anchor)
    .attr('font-size', labelSize)
    .attr('fill', (l) => l.mk.color)
    .attr('pointer-events', 'none')
    .text((l) => l.text);
}

/**
 * The work-precision diagram as a spec, worded by these options: log time per point against log max error, a
 * line per traced method (NaN errors are gaps), the marks (diamond defaults, red outlines for trouble, the chosen
 * one ringed, tolerance labels) over them, errors below ERROR_FLOOR on its dashed floor.
 */
export function workPrecisionSpec(
  o: WorkPrecisionSpecOptions = {},
): ChartSpec<WorkPrecisionData, never, WorkPrecisionText> {
  const labelOf = (sr: LabSeries) => o.methodLabels?.[sr.method] ?? sr.label;
  const tip = (mk: Marker) =>
    o.tooltip
      ? o.tooltip(mk.series, mk.point)
      : defaultTooltip(labelOf(mk.series), mk.point, o.defaultTolText ?? 'default');
  return {
    frame: workPrecisionFrame,
    curves: (data) => methodCurves(data, labelOf),
    xTickFormat: () => formatTimeTick,
    yTickFormat: () => formatErrorTick,
    legend: (_curves, _text, data) => methodLegend(data, o, labelOf),
    empty: (data, text) => (data.series.some((sr) => sr.points.some(isDrawable)) ? null : (text.emptyText ?? '')),
    over: {
      className: 'points',
      draw(g, data, frame) {
        const markers = curveMarkers(data.series, frame);
        const hl = data.highlight;
        const chosen = hl ? markers.filter((mk) => mk.series.method === hl.method && mk.point.tol === hl.tol) : [];
        drawMarkers(g, markers, tip);
        drawHighlight(g, chosen);
        const labelled = o.tolLabels !== false;
        drawTolLabels(g, labelled ? markers : [], labelled ? chosen : [], frame.iw, frame.ih);
      },
    },
  };
}

/**
 * The lab's work-precision diagram of these series as a drawing (on screen and for export): texts, wording and
 * the chosen point from options, at the size the drawing is asked for.
 */
export function workPrecisionDrawing(series: readonly LabSeries[], options: WorkPrecisionChartOptions): ChartDrawing {
  const { title, xLabel, yLabel, emptyText, highlight, ...wording } = options;
  return specDrawing(
    workPrecisionSpec(wording),
    { title, xLabel, yLabel, emptyText },
    { series, highlight },
    null,
    WORK_PRECISION_SIZE,
  );
}
