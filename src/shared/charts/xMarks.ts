import type { Selection } from 'd3-selection';
import { CHART_STYLE } from './chartFrame';
import type { ScaleLinear } from 'd3-scale';

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
  x: ScaleLinear<number, number>,
): { xPx: number; label: string }[] {
  const [d0, d1] = x.domain();
  return marks
    .filter((m) => Number.isFinite(m.xDeg) && m.xDeg >= Math.min(d0, d1) && m.xDeg <= Math.max(d0, d1))
    .map((m) => ({ xPx: x(m.xDeg), label: m.label }));
}

/**
 * Draws the marks in g (class x-mark per mark: a dashed line down height pixels and its label just above
 * the plot); marks outside the x domain or not finite are left out.
 */
export function drawXMarks(
  g: Selection<SVGGElement, unknown, null, undefined>,
  marks: readonly XMark[],
  x: ScaleLinear<number, number>,
  height: number,
): void {
  const shown = xMarkPositions(marks, x);
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
  sel
    .select('text')
    .attr('y', -3)
    .attr('text-anchor', 'middle')
    .attr('font-size', X_MARK_FONT_SIZE)
    .attr('fill', CHART_STYLE.muted)
    .text((d) => d.label);
}
