import { COLORS, FONTS, FONT_SIZES, STROKES } from '../theme/tokens';

/** Colours and sizes of the linkage drawing (CSS pixels), read from the design tokens. */
export const THEME = {
  background: COLORS.surface,
  grid: COLORS.grid,
  gridAxis: COLORS.gridAxis,
  gridText: COLORS.gridText,
  ground: COLORS.ground,
  crank: COLORS.crank,
  coupler: COLORS.coupler,
  couplerFill: COLORS.couplerFill,
  rocker: COLORS.rocker,
  trace: COLORS.trace,
  traceGhost: COLORS.traceGhost,
  ghost: COLORS.ghost,
  joint: COLORS.joint,
  jointStroke: COLORS.jointStroke,
  text: COLORS.text,
  textMuted: COLORS.textMuted,
  angle: COLORS.angle,
  couplerPoint: COLORS.couplerPoint,
  warning: COLORS.warning,
  warningFill: COLORS.warningFill,
  linkWidth: STROKES.link,
  jointRadius: STROKES.jointRadius,
  font: `${FONT_SIZES.canvas}px ${FONTS.sans}`,
  fontBold: `600 ${FONT_SIZES.canvasBold}px ${FONTS.sans}`,
} as const;
