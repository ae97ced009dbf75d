import type { Branch, Linkage } from '../solver/types';
import { fileNumber } from './format';

/** PNG export sizes: CSS pixel size, twice that, or 300 DPI at the on-screen physical size (96 CSS px per inch). */
export type PngSize = 'screen' | '2x' | 'print';

/** Pixel scale factor of each export size relative to CSS pixels. */
export const PNG_SCALE: Record<PngSize, number> = { screen: 1, '2x': 2, print: 300 / 96 };

/** Resolution written into each export size's pHYs chunk, dots per inch (so all print at the same physical size). */
export const PNG_DPI: Record<PngSize, number> = { screen: 96, '2x': 192, print: 300 };

const SUFFIX: Record<PngSize, string> = { screen: 'screen', '2x': '2x', print: '300dpi' };

/** What an exported file shows. */
export type ExportSubject = 'linkage' | 'theta3' | 'theta4' | 'both' | 'omega' | 'alpha' | 'convergence';

const SUBJECT: Record<ExportSubject, string> = {
  linkage: 'linkage',
  theta3: 'theta3-vs-theta2',
  theta4: 'theta4-vs-theta2',
  both: 'theta3-theta4-vs-theta2',
  omega: 'omega3-omega4-vs-theta2',
  alpha: 'alpha3-alpha4-vs-theta2',
  convergence: 'nr-convergence',
};

/** Common stem: fourbar_<r1>-<r2>-<r3>-<r4>_<branch>, ASCII only. */
export function fileStem(l: Linkage, branch: Branch): string {
  return `fourbar_${fileNumber(l.r1)}-${fileNumber(l.r2)}-${fileNumber(l.r3)}-${fileNumber(l.r4)}_${branch}`;
}

/** File name of a PNG export, e.g. fourbar_6-2-5-5_open_theta2-45_linkage_2x.png. */
export function pngFileName(
  l: Linkage,
  branch: Branch,
  theta2Deg: number,
  subject: ExportSubject,
  size: PngSize,
): string {
  const at =
    subject === 'linkage' || subject === 'convergence'
      ? `_theta2-${fileNumber(Math.round(theta2Deg * 100) / 100)}`
      : '';
  return `${fileStem(l, branch)}${at}_${SUBJECT[subject]}_${SUFFIX[size]}.png`;
}

/** File name of the cycle CSV, e.g. fourbar_6-2-5-5_open_cycle_n360.csv. */
export function csvFileName(l: Linkage, branch: Branch, samples: number): string {
  return `${fileStem(l, branch)}_cycle_n${samples}.csv`;
}

/** File name of a solver lab export, e.g. fourbar_6-2-5-5_open_work-precision_step1_2x.png or ..._step1.csv. */
export function labFileName(l: Linkage, branch: Branch, stepDeg: number, ext: 'png' | 'csv', size?: PngSize): string {
  const sz = ext === 'png' && size ? `_${SUFFIX[size]}` : '';
  return `${fileStem(l, branch)}_work-precision_step${fileNumber(stepDeg)}${sz}.${ext}`;
}

/** Animation file formats, as file extensions. */
export type AnimationExt = 'gif' | 'webm';

/** File name of an animation export, e.g. fourbar_6-2-5-5_open_cycle_120f_720p.gif (size 'screen' or '720p'). */
export function animationFileName(
  l: Linkage,
  branch: Branch,
  framesPerCycle: number,
  size: 'screen' | '720p',
  ext: AnimationExt,
): string {
  return `${fileStem(l, branch)}_cycle_${fileNumber(framesPerCycle)}f_${size}.${ext}`;
}

/** File name of an SVG export, e.g. fourbar_6-2-5-5_open_theta2-45_linkage.svg (the angle as in pngFileName). */
export function svgFileName(l: Linkage, branch: Branch, theta2Deg: number, subject: ExportSubject): string {
  return pngFileName(l, branch, theta2Deg, subject, 'screen').replace(/_screen\.png$/, '.svg');
}

/** File name of the solver lab's diagram as SVG, e.g. fourbar_6-2-5-5_open_work-precision_step1.svg. */
export function labSvgFileName(l: Linkage, branch: Branch, stepDeg: number): string {
  return `${fileStem(l, branch)}_work-precision_step${fileNumber(stepDeg)}.svg`;
}
