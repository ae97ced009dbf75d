import { scaleLog } from 'd3-scale';
import { line } from 'd3-shape';

/** One method's curve on the work-precision diagram: points (time per point in ns, max error in rad). */
export interface WorkPrecisionSeries {
  label: string;
  color: string;
  points: Array<{ nsPerPoint: number; maxError: number; tol?: number }>;
}

/** Options of workPrecisionSvg; sizes in CSS pixels. */
export interface WorkPrecisionSvgOptions {
  width?: number;
  height?: number;
  title?: string;
}

const ERROR_FLOOR = 1e-17;

function escapeXml(s: string): string {
  return s.replace(/[<>&"']/g, (c) => `&#${c.charCodeAt(0)};`);
}

/** A standalone SVG work-precision diagram (log time per point against log max angle error). */
export function workPrecisionSvg(series: WorkPrecisionSeries[], opts: WorkPrecisionSvgOptions = {}): string {
  const width = opts.width ?? 860;
  const height = opts.height ?? 440;
  const m = { top: 36, right: 270, bottom: 52, left: 72 };
  const all = series.flatMap((s) => s.points);
  const tMin = Math.min(...all.map((p) => p.nsPerPoint));
  const tMax = Math.max(...all.map((p) => p.nsPerPoint));
  const eMax = Math.max(...all.map((p) => Math.max(p.maxError, ERROR_FLOOR)));
  const x = scaleLog()
    .domain([tMin / 1.5, tMax * 1.5])
    .range([m.left, width - m.right]);
  const y = scaleLog()
    .domain([ERROR_FLOOR, Math.max(eMax * 10, 1e-2)])
    .range([height - m.bottom, m.top]);
  const out: string[] = [];
  out.push(
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" font-family="system-ui, sans-serif" font-size="12">`,
    `<rect width="${width}" height="${height}" fill="#fff"/>`,
  );
  if (opts.title)
    out.push(`<text x="${m.left}" y="22" font-size="14" font-weight="600">${escapeXml(opts.title)}</text>`);
  for (const t of x.ticks(6)) {
    const label = x.tickFormat(6, '~s')(t);
    if (!label) continue;
    out.push(
      `<line x1="${x(t)}" x2="${x(t)}" y1="${m.top}" y2="${height - m.bottom}" stroke="#eee"/>`,
      `<text x="${x(t)}" y="${height - m.bottom + 16}" text-anchor="middle" fill="#444">${label}</text>`,
    );
  }
  for (let e = -17; Math.pow(10, e) <= y.domain()[1]; e += 2) {
    const v = Math.pow(10, e);
    out.push(
      `<line x1="${m.left}" x2="${width - m.right}" y1="${y(v)}" y2="${y(v)}" stroke="#eee"/>`,
      `<text x="${m.left - 6}" y="${y(v) + 4}" text-anchor="end" fill="#444">1e${e}</text>`,
    );
  }
  out.push(
    `<rect x="${m.left}" y="${m.top}" width="${width - m.left - m.right}" height="${height - m.top - m.bottom}" fill="none" stroke="#888"/>`,
    `<text x="${(m.left + width - m.right) / 2}" y="${height - 12}" text-anchor="middle">median time per point (ns, log)</text>`,
    `<text transform="translate(18 ${(m.top + height - m.bottom) / 2}) rotate(-90)" text-anchor="middle">max angle error vs 60-digit reference (rad, log)</text>`,
  );
  const path = line<{ nsPerPoint: number; maxError: number }>()
    .x((p) => x(p.nsPerPoint))
    .y((p) => y(Math.max(p.maxError, ERROR_FLOOR)));
  series.forEach((s, i) => {
    // Trace each method over its tolerances, loosest first.
    const pts = [...s.points].sort((a, b) => (b.tol ?? 0) - (a.tol ?? 0));
    out.push(`<path d="${path(pts) ?? ''}" fill="none" stroke="${s.color}" stroke-width="2"/>`);
    for (const p of pts) {
      out.push(
        `<circle cx="${x(p.nsPerPoint)}" cy="${y(Math.max(p.maxError, ERROR_FLOOR))}" r="3.5" fill="${s.color}"><title>${escapeXml(
          `${s.label}${p.tol !== undefined ? ` tol ${p.tol}` : ''}: ${p.nsPerPoint.toFixed(0)} ns, ${p.maxError.toExponential(1)} rad`,
        )}</title></circle>`,
      );
    }
    const ly = m.top + 10 + i * 20;
    out.push(
      `<line x1="${width - m.right + 14}" x2="${width - m.right + 34}" y1="${ly}" y2="${ly}" stroke="${s.color}" stroke-width="2"/>`,
      `<text x="${width - m.right + 40}" y="${ly + 4}">${escapeXml(s.label)}</text>`,
    );
  });
  out.push('</svg>');
  return out.join('\n');
}
