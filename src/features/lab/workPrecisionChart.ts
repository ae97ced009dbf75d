import { axisBottom, axisLeft } from 'd3-axis';
import { scaleLog } from 'd3-scale';
import type { ScaleLogarithmic } from 'd3-scale';
import type { Selection } from 'd3-selection';
import { line, symbol, symbolCircle, symbolDiamond } from 'd3-shape';
import type { LabPoint, LabSeries } from '../../study/workPrecision';
import type { SweepMethod } from '../../solver/types';
import { CHART_COLORS } from '../../shared/theme/tokens';
import { formatSci } from '../../shared/format';
import type { Margins, SvgSel } from '../../shared/charts/chartFrame';
import {
  CHART_STYLE,
  child,
  estimateTextWidth,
  minus,
  prepareSvg,
  styleAxis,
  drawGridX,
  drawGridY,
  drawChartText,
} from '../../shared/charts/chartFrame';
import { dec, logTicks, niceLogDomain, niceOneTwoFiveDomain, tickCount } from '../../shared/charts/ticks';
import { placeLabels as placeBoxes } from '../../shared/canvas/labelPlacement';

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

/** Options of drawWorkPrecisionChart; sizes in CSS pixels. */
export interface WorkPrecisionChartOptions {
  width: number;
  height: number;
  title: string;
  /** x axis label, e.g. 'median time per point (ns)'. */
  xLabel: string;
  /** y axis label, e.g. 'max angle error (rad)'. */
  yLabel: string;
  /** The chosen method and tolerance, drawn with an orange ring; none by default. */
  highlight?: WorkPrecisionHighlight | null;
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
  /** Text shown in the middle when there is no point to plot. */
  emptyText?: string;
  /** Default { top: 55 plus 16 per extra legend row, right: 16, bottom: 40, left: 66 }; values given here win. */
  margins?: Partial<Margins>;
}

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

/** One entry of a method legend. */
export interface MethodLegendItem {
  label: string;
  color: string;
  /** 'line': plain line; 'curve': line with a dot; 'default': filled diamond; 'defaultKey': hollow diamond; 'failureKey': red-ringed dot. */
  kind: 'line' | 'curve' | 'default' | 'defaultKey' | 'failureKey';
}

/** Height of one legend row in pixels. */
export const LEGEND_ROW = 16;
const LEGEND_SAMPLE = 22;
const LEGEND_GAP = 14;

/** Wraps legend entries of these label widths into rows no wider than maxWidth; returns [x, row] per entry (pixels, row index). */
export function legendLayout(labelWidths: readonly number[], maxWidth: number): Array<[number, number]> {
  const out: Array<[number, number]> = [];
  let x = 0;
  let row = 0;
  for (const w of labelWidths) {
    const full = LEGEND_SAMPLE + w;
    if (x > 0 && x + full > maxWidth) {
      x = 0;
      row++;
    }
    out.push([x, row]);
    x += full + LEGEND_GAP;
  }
  return out;
}

/** Draws (or updates) a legend at (x, y) in the SVG that wraps into rows of at most maxWidth pixels; returns the number of rows. */
export function drawMethodLegend(
  s: SvgSel,
  items: readonly MethodLegendItem[],
  x: number,
  y: number,
  maxWidth: number,
): number {
  const layout = legendLayout(
    items.map((it) => estimateTextWidth(it.label)),
    maxWidth,
  );
  const legend = child(s, 'g', 'legend').attr('transform', `translate(${x},${y})`);
  const item = legend
    .selectAll<SVGGElement, MethodLegendItem>('g.item')
    .data(items)
    .join((enter) => {
      const g = enter.append('g').attr('class', 'item');
      g.append('line');
      g.append('path');
      g.append('text');
      return g;
    });
  item.attr('transform', (_d, i) => `translate(${layout[i][0]},${layout[i][1] * LEGEND_ROW})`);
  item
    .select('line')
    .attr('x1', 0)
    .attr('x2', 16)
    .attr('y1', 0)
    .attr('y2', 0)
    .attr('stroke', (d) => d.color)
    .attr('stroke-width', 1.75)
    .attr('display', (d) => (d.kind === 'curve' || d.kind === 'line' ? null : 'none'));
  item
    .select('path')
    .attr('transform', 'translate(8,0)')
    .attr('d', (d) => (d.kind === 'default' || d.kind === 'defaultKey' ? symbol(symbolDiamond, 70)() : '') ?? '')
    .attr('fill', (d) => (d.kind === 'default' ? d.color : CHART_STYLE.background))
    .attr('stroke', (d) =>
      d.kind === 'default' ? CHART_STYLE.background : d.kind === 'defaultKey' ? CHART_STYLE.muted : 'none',
    )
    .attr('stroke-width', (d) => (d.kind === 'defaultKey' ? 1.25 : 1));
  item
    .selectAll<SVGCircleElement, MethodLegendItem>('circle')
    .data((d) => (d.kind === 'curve' || d.kind === 'failureKey' ? [d] : []))
    .join('circle')
    .attr('cx', 8)
    .attr('cy', 0)
    .attr('r', (d) => (d.kind === 'curve' ? 3 : 3.5))
    .attr('fill', (d) => (d.kind === 'curve' ? d.color : CHART_STYLE.background))
    .attr('stroke', (d) => (d.kind === 'curve' ? CHART_STYLE.background : FAILURE_COLOR))
    .attr('stroke-width', (d) => (d.kind === 'curve' ? 1 : 2));
  item
    .select('text')
    .attr('x', 21)
    .attr('y', 4)
    .attr('fill', CHART_STYLE.text)
    .text((d) => d.label);
  return items.length ? layout[layout.length - 1][1] + 1 : 0;
}

/** One drawn marker (internal). */
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

type Curve = { sr: LabSeries } & ReturnType<typeof orderedCurvePoints>;
type G = Selection<SVGGElement, unknown, null, undefined>;
type LogScale = ScaleLogarithmic<number, number>;

/** Draws the legend (methods, then the diamond and red-outline keys when they apply); returns the plot margins it leaves. */
function drawLegendAndMargins(
  s: SvgSel,
  series: readonly LabSeries[],
  curves: readonly Curve[],
  options: WorkPrecisionChartOptions,
  labelOf: (sr: LabSeries) => string,
): Margins {
  const legendItems: MethodLegendItem[] = curves.map((c) => ({
    label: labelOf(c.sr),
    color: METHOD_COLORS[c.sr.method] ?? CHART_STYLE.muted,
    kind: c.traced.length > 0 ? 'curve' : 'default',
  }));
  const anyDefaultOfTraced = curves.some((c) => c.traced.length > 0 && c.defaultPoint);
  if (options.defaultLegend && anyDefaultOfTraced) {
    legendItems.push({ label: options.defaultLegend, color: CHART_STYLE.muted, kind: 'defaultKey' });
  }
  const anyTrouble = series.some((sr) => sr.points.some((p) => isDrawable(p) && hasTrouble(p)));
  if (options.failureLegend && anyTrouble) {
    legendItems.push({ label: options.failureLegend, color: FAILURE_COLOR, kind: 'failureKey' });
  }
  const legendRows = drawMethodLegend(s, legendItems, 14, 33, options.width - 28);
  return {
    top: options.margins?.top ?? 33 + Math.max(0, legendRows - 1) * LEGEND_ROW + 22,
    right: options.margins?.right ?? 16,
    bottom: options.margins?.bottom ?? 40,
    left: options.margins?.left ?? 66,
  };
}

/** Draws the grid, the dashed error floor (when a point sits on it) and both log axes. */
function drawAxesAndFloor(plot: G, x: LogScale, y: LogScale, iw: number, ih: number, anyFloored: boolean): void {
  const xTicks = logTicks(x.domain() as [number, number], tickCount(iw, 60));
  const yTicks = logTicks(
    y.domain() as [number, number],
    tickCount(ih, 24),
    anyFloored ? Math.round(Math.log10(ERROR_FLOOR)) : 0,
  );
  const grid = child(plot, 'g', 'grid');
  drawGridY(grid, iw, yTicks, y);
  drawGridX(grid, ih, xTicks, x);
  // The floor: everything at or below 1e-17 rad, exact answers included, is drawn on this dashed line.
  grid
    .selectAll<SVGLineElement, number>('line.floor')
    .data(anyFloored ? [ERROR_FLOOR] : [])
    .join('line')
    .attr('class', 'floor')
    .attr('x1', 0)
    .attr('x2', iw)
    .attr('y1', (d) => y(d))
    .attr('y2', (d) => y(d))
    .attr('stroke', CHART_STYLE.tolerance)
    .attr('stroke-dasharray', '3 3');
  const ax = child(plot, 'g', 'axis-x').attr('transform', `translate(0,${ih})`);
  ax.call(
    axisBottom(x)
      .tickValues(xTicks)
      .tickFormat((d) => formatTimeTick(Number(d)))
      .tickSizeOuter(0),
  );
  styleAxis(ax);
  const ay = child(plot, 'g', 'axis-y');
  ay.call(
    axisLeft(y)
      .tickValues(yTicks)
      .tickFormat((d) =>
        anyFloored && Number(d) === ERROR_FLOOR ? `≤${formatErrorTick(ERROR_FLOOR)}` : formatErrorTick(Number(d)),
      )
      .tickSizeOuter(0),
  );
  styleAxis(ay);
}

/** The markers of every curve in plot pixels: its drawable traced points, then its default. */
function curveMarkers(curves: readonly Curve[], x: LogScale, y: LogScale): Marker[] {
  const markers: Marker[] = [];
  const at = (sr: LabSeries, point: LabPoint, isDefault: boolean, color: string): Marker => ({
    series: sr,
    point,
    isDefault,
    color,
    x: x(point.nsPerPoint),
    y: y(plottedError(point.maxError)),
  });
  for (const c of curves) {
    const color = METHOD_COLORS[c.sr.method] ?? CHART_STYLE.muted;
    for (const p of c.traced) if (isDrawable(p)) markers.push(at(c.sr, p, false, color));
    if (c.defaultPoint) markers.push(at(c.sr, c.defaultPoint, true, color));
  }
  return markers;
}

/** Draws each traced method's line over its tolerances (gaps where a point is not drawable). */
function drawCurves(plot: G, curves: readonly Curve[], x: LogScale, y: LogScale): void {
  const gen = line<LabPoint>()
    .defined((p) => isDrawable(p))
    .x((p) => x(p.nsPerPoint))
    .y((p) => y(plottedError(p.maxError)));
  child(plot, 'g', 'curves')
    .selectAll<SVGPathElement, Curve>('path')
    .data(curves.filter((c) => c.traced.length > 0))
    .join('path')
    .attr('fill', 'none')
    .attr('stroke', (c) => METHOD_COLORS[c.sr.method] ?? CHART_STYLE.muted)
    .attr('stroke-width', 1.6)
    .attr('stroke-opacity', 0.85)
    .attr('stroke-linejoin', 'round')
    .attr('d', (c) => gen(c.traced) ?? '');
}

/** Draws the markers (dots, default diamonds, red outlines for trouble) with their tooltips. */
function drawMarkers(plot: G, markers: readonly Marker[], tip: (mk: Marker) => string): void {
  // Defaults first so the smaller traced dots stay visible on top of a diamond they coincide with.
  const ordered = [...markers.filter((mk) => mk.isDefault), ...markers.filter((mk) => !mk.isDefault)];
  const marks = child(plot, 'g', 'markers')
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
function drawHighlight(plot: G, chosen: readonly Marker[]): void {
  child(plot, 'g', 'highlight')
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
function drawTolLabels(plot: G, markers: readonly Marker[], chosen: readonly Marker[], iw: number, ih: number): void {
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
  child(plot, 'g', 'tol-labels')
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
 * Draws (or redraws in place) the lab's work-precision diagram: median time per point (ns) against
 * max angle error (rad), both log scales. Each traced method is a line over its tolerances (loosest
 * first); a method's default is a diamond; red outlines mark configurations that failed, jumped
 * branch or falsely converged; NaN errors are skipped; errors below ERROR_FLOOR sit on the floor.
 */
export function drawWorkPrecisionChart(
  svg: SVGSVGElement,
  series: readonly LabSeries[],
  options: WorkPrecisionChartOptions,
): void {
  const { width, height } = options;
  const s = prepareSvg(svg, width, height);
  const labelOf = (sr: LabSeries) => options.methodLabels?.[sr.method] ?? sr.label;
  const defaultTolText = options.defaultTolText ?? 'default';
  const curves: Curve[] = series.map((sr) => ({ sr, ...orderedCurvePoints(sr) }));
  const m = drawLegendAndMargins(s, series, curves, options, labelOf);
  const iw = Math.max(10, width - m.left - m.right);
  const ih = Math.max(10, height - m.top - m.bottom);
  const dom = workPrecisionDomains(series);
  const x = scaleLog().domain(dom.x).range([0, iw]).clamp(true);
  const y = scaleLog().domain(dom.y).range([ih, 0]).clamp(true);
  const plot = child(s, 'g', 'plot').attr('transform', `translate(${m.left},${m.top})`);
  const anyFloored = series.some((sr) => sr.points.some((p) => isDrawable(p) && p.maxError < ERROR_FLOOR));
  drawAxesAndFloor(plot, x, y, iw, ih, anyFloored);

  const markers = curveMarkers(curves, x, y);
  drawCurves(plot, curves, x, y);
  drawMarkers(plot, markers, (mk) =>
    options.tooltip
      ? options.tooltip(mk.series, mk.point)
      : defaultTooltip(labelOf(mk.series), mk.point, defaultTolText),
  );
  const hl = options.highlight;
  const chosen = hl ? markers.filter((mk) => mk.series.method === hl.method && mk.point.tol === hl.tol) : [];
  drawHighlight(plot, chosen);
  drawTolLabels(plot, options.tolLabels === false ? [] : markers, options.tolLabels === false ? [] : chosen, iw, ih);

  drawChartText(
    s,
    { title: options.title, xLabel: options.xLabel, yLabels: [{ text: options.yLabel, centerY: m.top + ih / 2 }] },
    m.left,
    iw,
    width,
    height,
    { plot, text: markers.length === 0 ? (options.emptyText ?? '') : null, centerY: m.top + ih / 2 },
  );
}
