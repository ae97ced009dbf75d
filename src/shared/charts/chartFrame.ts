import type { Selection } from 'd3-selection';
import { select } from 'd3-selection';
import { symbol, symbolDiamond } from 'd3-shape';
import { COLORS, FONTS, FONT_SIZES } from '../theme/tokens';

/** Chart margins in CSS pixels. */
export interface Margins {
  top: number;
  right: number;
  bottom: number;
  left: number;
}

/** Shared look of every chart; attributes (not CSS) so an exported SVG looks the same as on screen. */
export const CHART_STYLE = {
  font: FONTS.sans,
  fontSize: FONT_SIZES.chart,
  titleSize: FONT_SIZES.chartTitle,
  axisColor: COLORS.textMuted,
  gridColor: COLORS.chartGrid,
  background: COLORS.surface,
  text: COLORS.text,
  muted: COLORS.chartMuted,
  theta3: COLORS.coupler,
  theta4: COLORS.rocker,
  marker: COLORS.marker,
  residual: COLORS.residual,
  tolerance: COLORS.tolerance,
} as const;

/** The SVG root as a d3 selection. */
export type SvgSel = Selection<SVGSVGElement, unknown, null, undefined>;

/** Returns the child of parent with this class, creating it (tag) on first use. */
export function child<K extends keyof SVGElementTagNameMap, P extends SVGElement>(
  parent: Selection<P, unknown, null, undefined>,
  tag: K,
  cls: string,
): Selection<SVGElementTagNameMap[K], unknown, null, undefined> {
  const node = (parent.node() as SVGElement).querySelector<SVGElementTagNameMap[K]>(`:scope > ${tag}.${cls}`);
  if (node) return select(node);
  const created = (parent.node() as SVGElement).appendChild(
    (parent.node() as SVGElement).ownerDocument.createElementNS('http://www.w3.org/2000/svg', tag),
  );
  created.setAttribute('class', cls);
  return select(created as SVGElementTagNameMap[K]);
}

/** Sets size, font and colour on the SVG root and paints the background; returns the selection. */
export function prepareSvg(svg: SVGSVGElement, width: number, height: number): SvgSel {
  const s = select(svg)
    .attr('width', width)
    .attr('height', height)
    .attr('viewBox', `0 0 ${width} ${height}`)
    .attr('font-family', CHART_STYLE.font)
    .attr('font-size', CHART_STYLE.fontSize)
    .attr('color', CHART_STYLE.axisColor);
  child(s, 'rect', 'bg').attr('width', width).attr('height', height).attr('fill', CHART_STYLE.background);
  return s;
}

/** Tidies a d3 axis group: colour, no domain tick caps clutter. */
export function styleAxis(g: Selection<SVGGElement, unknown, null, undefined>): void {
  g.attr('color', CHART_STYLE.axisColor).attr('font-family', CHART_STYLE.font).attr('font-size', CHART_STYLE.fontSize);
}

/** Replaces an ASCII hyphen-minus used as a sign with a typographic minus. */
export function minus(s: string): string {
  return s.replace(/^-/, '\u2212').replace(/e-/, 'e\u2212');
}

/** How a legend entry's sample is drawn: a line (dashed when faint), a line through a dot, a diamond (filled or hollow), a ring. */
export type LegendSymbol = 'line' | 'line-dot' | 'diamond' | 'hollow-diamond' | 'ring';

/** One legend entry: a sample (default a line) and its label. */
export interface LegendItem {
  label: string;
  color: string;
  faint?: boolean;
  /** Default 'line'. */
  symbol?: LegendSymbol;
}

/** Rough label width in CSS pixels at the chart font size; labels are not measured so export and screen agree. */
export function estimateTextWidth(text: string, fontSize: number = CHART_STYLE.fontSize): number {
  let w = 0;
  for (const ch of text) w += ch.charCodeAt(0) > 0x2e80 ? fontSize : fontSize * 0.56;
  return w;
}

/** A box in CSS pixels: left, top, right, bottom. */
export interface TextBox {
  x0: number;
  y0: number;
  x1: number;
  y1: number;
}

/** Height of one legend row, CSS pixels. */
export const LEGEND_ROW = 16;
/** A legend entry's sample and the gap before its label, then the space before the next entry; CSS pixels. */
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

/** Where each entry of a legend at most maxWidth pixels wide goes: [x, row] from its origin. */
function legendPlaces(items: readonly LegendItem[], maxWidth: number): Array<[number, number]> {
  return legendLayout(
    items.map((it) => estimateTextWidth(it.label)),
    maxWidth,
  );
}

/** Rows a legend of these entries takes at most maxWidth pixels wide (0 without entries). */
export function legendRows(items: readonly LegendItem[], maxWidth: number): number {
  const places = legendPlaces(items, maxWidth);
  return places.length ? places[places.length - 1][1] + 1 : 0;
}

/**
 * The boxes (CSS pixels, SVG coordinates) a legend at (x, y), wrapped at maxWidth, covers, one per entry: its
 * sample and label, from a font-size above the label's baseline (y + 4) to a quarter of it below (descenders).
 */
export function legendBoxes(items: readonly LegendItem[], x: number, y: number, maxWidth = Infinity): TextBox[] {
  const places = legendPlaces(items, maxWidth);
  const f = CHART_STYLE.fontSize;
  return items.map((it, i) => {
    const [dx, row] = places[i];
    const top = y + row * LEGEND_ROW;
    return { x0: x + dx, y0: top + 4 - f, x1: x + dx + 21 + estimateTextWidth(it.label), y1: top + 4 + f / 4 };
  });
}

/** True for the samples drawn as a line (and a dot on it). */
const isLine = (d: LegendItem) => d.symbol === undefined || d.symbol === 'line' || d.symbol === 'line-dot';
const isDiamond = (d: LegendItem) => d.symbol === 'diamond' || d.symbol === 'hollow-diamond';

/**
 * Draws (or updates) a legend starting at (x, y) in the SVG, sample then label, left to right, wrapped into rows of
 * at most maxWidth pixels (LEGEND_ROW apart); returns the number of rows.
 */
export function drawLegend(s: SvgSel, items: readonly LegendItem[], x: number, y: number, maxWidth = Infinity): number {
  const legend = child(s, 'g', 'legend').attr('transform', `translate(${x},${y})`);
  const places = legendPlaces(items, maxWidth);
  const item = legend
    .selectAll<SVGGElement, LegendItem>('g.item')
    .data(items)
    .join((enter) => {
      const g = enter.append('g').attr('class', 'item');
      g.append('line');
      g.append('text');
      return g;
    });
  item.attr('transform', (_d, i) => `translate(${places[i][0]},${places[i][1] * LEGEND_ROW})`);
  item
    .select('line')
    .attr('display', (d) => (isLine(d) ? null : 'none'))
    .attr('x1', 0)
    .attr('x2', 16)
    .attr('y1', 0)
    .attr('y2', 0)
    .attr('stroke', (d) => d.color)
    .attr('stroke-width', (d) => (d.faint ? 1.25 : 2))
    .attr('stroke-dasharray', (d) => (d.faint ? '4 3' : null));
  item
    .selectAll<SVGPathElement, LegendItem>('path')
    .data((d) => (isDiamond(d) ? [d] : []))
    .join('path')
    .attr('transform', 'translate(8,0)')
    .attr('d', symbol(symbolDiamond, 70)() ?? '')
    .attr('fill', (d) => (d.symbol === 'diamond' ? d.color : CHART_STYLE.background))
    .attr('stroke', (d) => (d.symbol === 'diamond' ? CHART_STYLE.background : d.color))
    .attr('stroke-width', (d) => (d.symbol === 'diamond' ? 1 : 1.25));
  // A dot on the line (a curve through points), or a ring of the entry's colour alone.
  item
    .selectAll<SVGCircleElement, LegendItem>('circle')
    .data((d) => (d.symbol === 'line-dot' || d.symbol === 'ring' ? [d] : []))
    .join('circle')
    .attr('cx', 8)
    .attr('cy', 0)
    .attr('r', (d) => (d.symbol === 'ring' ? 3.5 : 3))
    .attr('fill', (d) => (d.symbol === 'ring' ? CHART_STYLE.background : d.color))
    .attr('stroke', (d) => (d.symbol === 'ring' ? d.color : CHART_STYLE.background))
    .attr('stroke-width', (d) => (d.symbol === 'ring' ? 2 : 1));
  item
    .select('text')
    .attr('x', 21)
    .attr('y', 4)
    .attr('fill', CHART_STYLE.text)
    .text((d) => d.label);
  return legendRows(items, maxWidth);
}

/** Horizontal lines of class cls at these values (y maps a value to pixels) across width pixels in g; dashed when dash is given. */
export function drawHLines(
  g: Selection<SVGGElement, unknown, null, undefined>,
  cls: string,
  values: readonly number[],
  width: number,
  y: (v: number) => number,
  stroke: string,
  dash: string | null = null,
): void {
  g.selectAll<SVGLineElement, number>(`line.${cls}`)
    .data(values)
    .join('line')
    .attr('class', cls)
    .attr('x1', 0)
    .attr('x2', width)
    .attr('y1', (d) => y(d))
    .attr('y2', (d) => y(d))
    .attr('stroke', stroke)
    .attr('stroke-dasharray', dash);
}

/** Horizontal grid lines (class gy) at yTicks across width pixels, in group g. */
export function drawGridY(
  g: Selection<SVGGElement, unknown, null, undefined>,
  width: number,
  yTicks: readonly number[],
  y: (v: number) => number,
): void {
  drawHLines(g, 'gy', yTicks, width, y, CHART_STYLE.gridColor);
}

/** Vertical grid lines (class gx) at xTicks down height pixels, in group g. */
export function drawGridX(
  g: Selection<SVGGElement, unknown, null, undefined>,
  height: number,
  xTicks: readonly number[],
  x: (v: number) => number,
): void {
  g.selectAll<SVGLineElement, number>('line.gx')
    .data(xTicks)
    .join('line')
    .attr('class', 'gx')
    .attr('y1', 0)
    .attr('y2', height)
    .attr('x1', (d) => x(d))
    .attr('x2', (d) => x(d))
    .attr('stroke', CHART_STYLE.gridColor);
}

/** A rotated y-axis label and the vertical centre of the panel it names (pixels from the SVG top). */
export interface YLabel {
  text: string;
  centerY: number;
}

/** Texts around a chart's plot area: the title, the x label and one y label per panel. */
export interface ChartText {
  title: string;
  xLabel: string;
  yLabels: readonly YLabel[];
}

/**
 * Draws the title (top left), the x label centred under the plot (plotLeft, plotWidth) and the rotated
 * y labels; with emptyText given (no data), the axis labels and plot are hidden and the text is centred
 * at emptyCenterY instead. Sizes in CSS pixels.
 */
export function drawChartText(
  s: SvgSel,
  text: ChartText,
  plotLeft: number,
  plotWidth: number,
  width: number,
  height: number,
  empty?: { plot: Selection<SVGGElement, unknown, null, undefined>; text: string | null; centerY: number },
): void {
  const hide = empty?.text != null ? 'none' : null;
  child(s, 'text', 'title')
    .attr('x', 14)
    .attr('y', 17)
    .attr('font-size', CHART_STYLE.titleSize)
    .attr('font-weight', 600)
    .attr('fill', CHART_STYLE.text)
    .text(text.title);
  child(s, 'text', 'xlabel')
    .attr('display', hide)
    .attr('x', plotLeft + plotWidth / 2)
    .attr('y', height - 6)
    .attr('text-anchor', 'middle')
    .attr('fill', CHART_STYLE.muted)
    .text(text.xLabel);
  text.yLabels.forEach((yl, i) => {
    child(s, 'text', i === 0 ? 'ylabel' : `ylabel-${i}`)
      .attr('display', hide)
      .attr('transform', `translate(12,${yl.centerY}) rotate(-90)`)
      .attr('text-anchor', 'middle')
      .attr('fill', CHART_STYLE.muted)
      .text(yl.text);
  });
  if (!empty) return;
  empty.plot.attr('display', hide);
  child(s, 'text', 'empty')
    .attr('x', width / 2)
    .attr('y', empty.centerY)
    .attr('text-anchor', 'middle')
    .attr('fill', CHART_STYLE.muted)
    .text(empty.text ?? '');
}

/** Whether two sets of chart texts are equal: the same keys with the same values. */
export function sameChartTexts<T extends object>(a: T, b: T): boolean {
  const ka = Object.keys(a) as (keyof T)[];
  return ka.length === Object.keys(b).length && ka.every((k) => a[k] === b[k]);
}
