import type { DrawContext } from './drawContext';
import { THEME } from './canvasTheme';
import { STROKES } from '../theme/tokens';
import type { ViewTransform } from './view';
import { gridLines, toScreenX, toScreenY } from './view';

/**
 * Draws the world grid of a view: lines about targetPx apart (default 64) at round world steps, the axes darker,
 * each on a pixel's centre so it stays one device line sharp. Nothing when the grid would be too dense.
 */
export function drawGrid(ctx: DrawContext, v: ViewTransform, targetPx = 64): void {
  const g = gridLines(v, targetPx);
  if (!g) return;
  ctx.lineWidth = STROKES.grid;
  for (let i = g.i0; i <= g.i1; i++) {
    const x = Math.round(toScreenX(v, i * g.step)) + 0.5;
    ctx.strokeStyle = i === 0 ? THEME.gridAxis : THEME.grid;
    ctx.beginPath();
    ctx.moveTo(x, 0);
    ctx.lineTo(x, v.height);
    ctx.stroke();
  }
  for (let j = g.j0; j <= g.j1; j++) {
    const y = Math.round(toScreenY(v, j * g.step)) + 0.5;
    ctx.strokeStyle = j === 0 ? THEME.gridAxis : THEME.grid;
    ctx.beginPath();
    ctx.moveTo(0, y);
    ctx.lineTo(v.width, y);
    ctx.stroke();
  }
}
