/**
 * Design tokens: the one source of colours, fonts and line widths. The CSS variables (see cssVariables),
 * the canvas drawing (shared/canvas/canvasTheme.ts) and the d3 charts (shared/charts/chartFrame.ts) all read from here.
 * Colours are CSS colour strings; sizes are CSS pixels.
 */

/** Font stacks: the UI's sans-serif (with Traditional Chinese fallbacks) and the monospace for numbers. */
export const FONTS = {
  sans: 'system-ui, -apple-system, "Segoe UI", "Noto Sans TC", "PingFang TC", "Microsoft JhengHei", sans-serif',
  mono: 'ui-monospace, "SFMono-Regular", Menlo, Consolas, "Liberation Mono", monospace',
} as const;

/**
 * Colours shared by the page, the canvas and the charts. Canvas text colours reach 4.5:1 against the canvas
 * background and its line colours 3:1 (WCAG 1.4.3 / 1.4.11), checked by tests/shared/linkage/contrast.test.ts;
 * grid lines, fills and halos are the only exceptions.
 */
export const COLORS = {
  pageBackground: '#f3f5f8',
  surface: '#ffffff',
  /** Side panels and inset boxes: a shade off the surface. */
  surfaceAlt: '#fbfcfd',
  surfaceSunken: '#f8fafc',
  /** Hover background of plain buttons. */
  hover: '#f5f7fa',
  border: '#dfe4eb',
  borderStrong: '#c5cdd8',
  text: '#1f2937',
  textMuted: '#4b5563',
  textSubtle: '#667085',
  accent: '#1e3a5f',
  accent2: '#2563eb',
  accent2Hover: '#1d4ed8',
  accentSoft: '#e8effa',
  /** Text, icons and outlines on the accent (the top bar): solid, dimmed, a faint fill, a border, a hover fill. */
  onAccent: '#ffffff',
  onAccentMuted: 'rgba(255, 255, 255, 0.82)',
  onAccentFaint: 'rgba(255, 255, 255, 0.12)',
  onAccentBorder: 'rgba(255, 255, 255, 0.35)',
  onAccentHover: 'rgba(255, 255, 255, 0.1)',
  /** Focus ring on the accent background, where the blue ring would vanish. */
  focusOnAccent: '#fbbf24',
  /** Translucent surface over the canvas (its tool buttons). */
  overlay: 'rgba(255, 255, 255, 0.92)',
  shadow: 'rgba(16, 24, 40, 0.04)',
  danger: '#b42318',
  dangerSoft: '#fef3f2',
  dangerBorder: '#fecdca',
  ok: '#067647',
  okSoft: '#ecfdf3',
  warn: '#b54708',
  warnSoft: '#fffaeb',
  /** A highlighted table row (the chosen method in the lab). */
  highlightRow: '#fff7ed',
  /** Links and their series in the plots: ground, crank (theta2), coupler (theta3), rocker (theta4). */
  ground: '#6b7280',
  groundFill: '#eef1f5',
  crank: '#2563eb',
  coupler: '#047857',
  couplerFill: 'rgba(4, 120, 87, 0.12)',
  rocker: '#9333ea',
  /** The coupler curve of the current circuit and (dashed) the other circuits. */
  trace: '#e2590c',
  traceGhost: '#e46a26',
  /** The other branch's links, dashed. */
  ghost: '#7c8798',
  joint: '#ffffff',
  jointStroke: '#1f2937',
  angle: '#b45309',
  /** Dashed zero-angle references at A and O4. */
  reference: '#7c8798',
  couplerPoint: '#9a3412',
  /** Velocity and acceleration arrows on the canvas and their series in the rate plots. */
  velocity: '#0e7490',
  acceleration: '#be185d',
  /** Pin-force arrows on the canvas and the input torque in the force plots. */
  force: '#dc2626',
  /** White halo behind canvas labels, so they read over lines. */
  labelHalo: 'rgba(255, 255, 255, 0.9)',
  grid: '#e8ecf1',
  gridAxis: '#cbd3dd',
  gridText: '#667085',
  chartGrid: '#edf0f4',
  chartMuted: '#6b7280',
  marker: '#e2590c',
  residual: '#2563eb',
  tolerance: '#9ca3af',
  /** Outlines of the dead-centre poses and the swing arc; instant centres and their construction lines. */
  deadCentre: '#64748b',
  instantCentre: '#0e7490',
  /** Transmission plot: the usable band's fill and the stretches of mu outside it. */
  muBandFill: 'rgba(6, 118, 71, 0.1)',
  muOutside: '#b91c1c',
  muOutsideFill: 'rgba(185, 28, 28, 0.08)',
  warningFill: 'rgba(254, 242, 242, 0.94)',
  warning: '#b91c1c',
} as const;

/** Line widths, dash patterns and radii of the linkage drawing (CSS pixels). */
export const STROKES = {
  link: 5,
  jointRadius: 5,
  /** Ground pivots O2 and O4 and the coupler point P. */
  pivotRadius: 6,
  couplerPointRadius: 5,
  jointOutline: 1.75,
  ghost: 2,
  ghostJointRadius: 3.5,
  ground: 1.5,
  groundHatch: 1,
  trace: 2,
  traceGhost: 1.25,
  arc: 1.25,
  reference: 1,
  grid: 1,
  couplerPlate: 1,
  /** Width of the white halo stroked behind each label. */
  labelHalo: 3,
  ghostDash: [5, 4],
  traceGhostDash: [4, 4],
  groundDash: [6, 4],
  referenceDash: [3, 3],
  deadCentre: 1.5,
  deadCentreDash: [2, 3],
  construction: 1,
  constructionDash: [6, 3, 1, 3],
  instantCentreRadius: 4,
  /** Edge marker of an off-screen instant centre: inset from the canvas edge and arrow length. */
  edgeInset: 14,
  edgeArrow: 10,
  /** Velocity and acceleration arrows: shaft width, head length and width, dash of a clamped arrow. */
  vector: 2,
  vectorHead: 9,
  vectorHeadWidth: 7,
  vectorClampDash: [6, 3],
} as const;

/** The canvas's zoom buttons (CSS pixels): inset from the top-right corner, button size, gap, how many. */
export const CANVAS_TOOLS = {
  insetPx: 8,
  buttonPx: 30,
  gapPx: 4,
  count: 3,
} as const;

/**
 * The layout's breakpoints (CSS pixels, widest viewport of each): the phone layout (one column, the phone bar at
 * the bottom) and the tablet layout (numbers below). src/app/layout.css's media queries use the same numbers.
 */
export const BREAKPOINTS = {
  phoneMaxPx: 720,
  tabletMaxPx: 1100,
} as const;

/** The media query of the phone layout. */
export const PHONE_MEDIA = `(max-width: ${BREAKPOINTS.phoneMaxPx}px)`;

/** Font sizes (CSS pixels): canvas labels, chart ticks and chart titles. */
export const FONT_SIZES = {
  canvas: 12,
  canvasBold: 13,
  chart: 11,
  chartTitle: 12.5,
} as const;

/** The CSS custom properties fed from the tokens (set on :root at startup by shared/theme/applyTokens.ts). */
export function cssVariables(): Record<string, string> {
  return {
    '--bg': COLORS.pageBackground,
    '--card': COLORS.surface,
    '--surface-alt': COLORS.surfaceAlt,
    '--surface-sunken': COLORS.surfaceSunken,
    '--hover': COLORS.hover,
    '--border': COLORS.border,
    '--border-strong': COLORS.borderStrong,
    '--text': COLORS.text,
    '--text-muted': COLORS.textMuted,
    '--muted': COLORS.textSubtle,
    '--accent': COLORS.accent,
    '--accent-2': COLORS.accent2,
    '--accent-2-hover': COLORS.accent2Hover,
    '--accent-soft': COLORS.accentSoft,
    '--on-accent': COLORS.onAccent,
    '--on-accent-muted': COLORS.onAccentMuted,
    '--on-accent-faint': COLORS.onAccentFaint,
    '--on-accent-border': COLORS.onAccentBorder,
    '--on-accent-hover': COLORS.onAccentHover,
    '--focus-on-accent': COLORS.focusOnAccent,
    '--overlay': COLORS.overlay,
    '--shadow': COLORS.shadow,
    '--danger': COLORS.danger,
    '--danger-soft': COLORS.dangerSoft,
    '--danger-border': COLORS.dangerBorder,
    '--ok': COLORS.ok,
    '--ok-soft': COLORS.okSoft,
    '--warn': COLORS.warn,
    '--warn-soft': COLORS.warnSoft,
    '--highlight-row': COLORS.highlightRow,
    '--bad': COLORS.warning,
    '--font': FONTS.sans,
    '--mono': FONTS.mono,
    '--crank': COLORS.crank,
    '--coupler': COLORS.coupler,
    '--rocker': COLORS.rocker,
    '--trace': COLORS.trace,
    '--canvas-tools-inset': `${CANVAS_TOOLS.insetPx}px`,
    '--canvas-tool-size': `${CANVAS_TOOLS.buttonPx}px`,
    '--canvas-tools-gap': `${CANVAS_TOOLS.gapPx}px`,
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
