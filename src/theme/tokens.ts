/**
 * Design tokens: the one source of colours, fonts and line widths. The CSS variables (see cssVariables),
 * the canvas drawing (render/theme.ts) and the d3 charts (charts/chartFrame.ts) all read from here.
 * Colours are CSS colour strings; sizes are CSS pixels.
 */

/** Font stacks: the UI's sans-serif (with Traditional Chinese fallbacks) and the monospace for numbers. */
export const FONTS = {
  sans: 'system-ui, -apple-system, "Segoe UI", "Noto Sans TC", "PingFang TC", "Microsoft JhengHei", sans-serif',
  mono: 'ui-monospace, "SFMono-Regular", Menlo, Consolas, "Liberation Mono", monospace',
} as const;

/** Colours shared by the page, the canvas and the charts. */
export const COLORS = {
  pageBackground: '#f3f5f8',
  surface: '#ffffff',
  border: '#dfe4eb',
  borderStrong: '#c5cdd8',
  text: '#1f2937',
  textMuted: '#4b5563',
  textSubtle: '#667085',
  accent: '#1e3a5f',
  accent2: '#2563eb',
  accentSoft: '#e8effa',
  danger: '#b42318',
  dangerSoft: '#fef3f2',
  ok: '#067647',
  okSoft: '#ecfdf3',
  warn: '#b54708',
  warnSoft: '#fffaeb',
  /** Links and their series in the plots: ground, crank (theta2), coupler (theta3), rocker (theta4). */
  ground: '#6b7280',
  crank: '#2563eb',
  coupler: '#0f9d76',
  couplerFill: 'rgba(15, 157, 118, 0.12)',
  rocker: '#9333ea',
  trace: '#f97316',
  traceGhost: 'rgba(249, 115, 22, 0.28)',
  ghost: 'rgba(100, 116, 139, 0.38)',
  joint: '#ffffff',
  jointStroke: '#1f2937',
  angle: '#b45309',
  couplerPoint: '#9a3412',
  grid: '#e8ecf1',
  gridAxis: '#cbd3dd',
  gridText: '#8592a3',
  chartGrid: '#edf0f4',
  chartMuted: '#6b7280',
  marker: '#f97316',
  residual: '#2563eb',
  tolerance: '#9ca3af',
  warningFill: 'rgba(254, 242, 242, 0.94)',
  warning: '#b91c1c',
} as const;

/** Line widths and radii of the linkage drawing (CSS pixels). */
export const STROKES = {
  link: 5,
  jointRadius: 5,
} as const;

/** Font sizes (CSS pixels): canvas labels, chart ticks and chart titles. */
export const FONT_SIZES = {
  canvas: 12,
  canvasBold: 13,
  chart: 11,
  chartTitle: 12.5,
} as const;

/** The CSS custom properties fed from the tokens (set on :root by applyCssVariables). */
export function cssVariables(): Record<string, string> {
  return {
    '--bg': COLORS.pageBackground,
    '--card': COLORS.surface,
    '--border': COLORS.border,
    '--border-strong': COLORS.borderStrong,
    '--text': COLORS.text,
    '--muted': COLORS.textSubtle,
    '--accent': COLORS.accent,
    '--accent-2': COLORS.accent2,
    '--accent-soft': COLORS.accentSoft,
    '--danger': COLORS.danger,
    '--danger-soft': COLORS.dangerSoft,
    '--ok': COLORS.ok,
    '--ok-soft': COLORS.okSoft,
    '--warn': COLORS.warn,
    '--warn-soft': COLORS.warnSoft,
    '--font': FONTS.sans,
    '--mono': FONTS.mono,
    '--crank': COLORS.crank,
    '--coupler': COLORS.coupler,
    '--rocker': COLORS.rocker,
    '--trace': COLORS.trace,
  };
}

/** Chart-only colours: one per lab method (work-precision and cycle charts), failure outlines, bands of unassembled stretches. */
export const CHART_COLORS = {
  methodClosedForm: '#0f9d76',
  methodClosedFormPolish: '#2563eb',
  methodNewton: '#9333ea',
  methodNewtonNoPredictor: '#a16207',
  methodSeed: '#475569',
  /** Outline of a lab marker whose configuration failed, jumped branch or falsely converged. */
  failure: '#dc2626',
  /** Background band where the linkage cannot assemble. */
  unassembledBand: '#f3f4f6',
} as const;
