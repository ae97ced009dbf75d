import type { Selection } from 'd3-selection';
import type { TextBox } from './chartFrame';
import { CHART_STYLE, estimateTextWidth } from './chartFrame';
import type { ScaleContinuousNumeric } from 'd3-scale';

/** A faint vertical rule on a theta2 axis with a small label: a dead centre, say. xDeg in the axis's degrees. */
export interface XMark {
  xDeg: number;
  label: string;
}

/** Font size of the marks' labels, CSS pixels. */
export const X_MARK_FONT_SIZE = 10;

/** The marks to draw and their x in plot pixels: those with a finite xDeg inside the scale's domain, in order. */
export function xMarkPositions(
  marks: readonly XMark[],
  x: ScaleContinuousNumeric<number, number>,
): { xPx: number; label: string }[] {
  const [d0, d1] = x.domain();
  return marks
    .filter((m) => Number.isFinite(m.xDeg) && m.xDeg >= Math.min(d0, d1) && m.xDeg <= Math.max(d0, d1))
    .map((m) => ({ xPx: x(m.xDeg), label: m.label }));
}

/** Baselines (plot pixels, y down from the plot's top) of a mark's label: above the plot, else just inside it. */
export const X_MARK_BASELINES = { above: -3, inside: X_MARK_FONT_SIZE + 2 } as const;

/** The box (plot pixels) of a mark's label centred at xPx on a baseline. */
function xMarkLabelBox(xPx: number, label: string, baseline: number): TextBox {
  const half = estimateTextWidth(label, X_MARK_FONT_SIZE) / 2;
  return { x0: xPx - half, y0: baseline - X_MARK_FONT_SIZE, x1: xPx + half, y1: baseline + X_MARK_FONT_SIZE / 4 };
}

function boxesMeet(a: TextBox, b: TextBox): boolean {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

/**
 * The baseline of each mark's label (plot pixels): above the plot where it meets neither a box to avoid (the
 * legend, in plot pixels) nor a label set before it, else just inside the plot's top (issue 19: "fold." was drawn
 * over "(other branch)"). Labels are set in the order given.
 */
export function xMarkBaselines(shown: readonly { xPx: number; label: string }[], avoid: readonly TextBox[]): number[] {
  const taken: TextBox[] = [...avoid];
  return shown.map((m) => {
    const above = xMarkLabelBox(m.xPx, m.label, X_MARK_BASELINES.above);
    const baseline = taken.some((b) => boxesMeet(b, above)) ? X_MARK_BASELINES.inside : X_MARK_BASELINES.above;
    taken.push(xMarkLabelBox(m.xPx, m.label, baseline));
    return baseline;
  });
}

/**
 * Draws the marks in g (class x-mark per mark: a dashed line down height pixels and its label just above
 * the plot, or just inside its top where the label would meet a box of avoid, plot pixels: the legend); marks
 * outside the x domain or not finite are left out.
 */
export function drawXMarks(
  g: Selection<SVGGElement, unknown, null, undefined>,
  marks: readonly XMark[],
  x: ScaleContinuousNumeric<number, number>,
  height: number,
  avoid: readonly TextBox[] = [],
): void {
  const shown = xMarkPositions(marks, x);
  const baselines = xMarkBaselines(shown, avoid);
  const sel = g
    .selectAll<SVGGElement, { xPx: number; label: string }>('g.x-mark')
    .data(shown)
    .join((enter) => {
      const m = enter.append('g').attr('class', 'x-mark');
      m.append('line');
      m.append('text');
      return m;
    });
  sel.attr('transform', (d) => `translate(${d.xPx},0)`);
  sel
    .select('line')
    .attr('y1', 0)
    .attr('y2', height)
    .attr('stroke', CHART_STYLE.muted)
    .attr('stroke-opacity', 0.6)
    .attr('stroke-dasharray', '2 3');
  // Inside the plot a label may cross a curve or a grid line: a halo of the background keeps it legible.
  sel
    .select('text')
    .attr('y', (_d, i) => baselines[i])
    .attr('text-anchor', 'middle')
    .attr('font-size', X_MARK_FONT_SIZE)
    .attr('fill', CHART_STYLE.muted)
    .attr('stroke', CHART_STYLE.background)
    .attr('stroke-width', 3)
    .attr('stroke-linejoin', 'round')
    .attr('paint-order', 'stroke')
    .text((d) => d.label);
}
