import { downloadText } from '../../../shared/canvas/download';
import { exportDrawingPng, exportDrawingSvg } from '../../../shared/canvas/exportDrawing';
import type { ViewTransform } from '../../../shared/canvas/view';
import type { PathSolution } from '../../../synthesis/types';
import type { PathScene } from './drawPathScene';
import { drawPathScene } from './drawPathScene';
import { resultsToCsv } from './resultsCsv';

/** Downloads the candidates as synthesis-results.csv (resultsToCsv). */
export function exportResultsCsv(solutions: readonly PathSolution[]): void {
  downloadText(resultsToCsv(solutions), 'synthesis-results.csv', 'text/csv;charset=utf-8');
}

/** Downloads the synthesis canvas as synthesis.svg. */
export function exportPathSvg(scene: PathScene, view: ViewTransform): void {
  exportDrawingSvg((ctx) => drawPathScene(ctx, scene, view), view.width, view.height, 'synthesis');
}

/** Downloads the synthesis canvas as synthesis.png, drawn afresh at twice the CSS size (192 dpi). */
export async function exportPathPng(scene: PathScene, view: ViewTransform): Promise<void> {
  await exportDrawingPng((ctx) => drawPathScene(ctx, scene, view), view.width, view.height, 'synthesis');
}
