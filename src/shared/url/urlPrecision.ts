/** Decimals of angles in degrees in the URL: 1e-9 deg keeps any typed value and drops float noise from Play. */
export const URL_ANGLE_DECIMALS = 9;
/** Significant digits of the view's zoom and pan in the URL (sub-pixel at any canvas size). */
export const URL_VIEW_DIGITS = 6;
