/**
 * In-page part of the chart update benchmark: precomputes the plot samples of the default linkage
 * (6-2-5-5, open) for a run of r3 values, then times the JavaScript of updating the two separate angle
 * plots (inputs, curves and marker) for each step, the way AnglePlotsPanel does when an r3 answer arrives.
 */
import { plotDegrees } from '../../src/shared/charts/chartInputs';
import { adaptiveGrid, degToRad, radToDeg, solveClosedForm, sweep } from '../../src/solver';
import type { PlotSeries, PointResponse } from '../../src/shared/solution';
import { makeAnglePlots } from './plots';

/** Result of one run: milliseconds of JS per r3 step. */
export interface BenchRun {
  msPerUpdate: number[];
}

function fakeCycle(r3: number, pixels: number): { plot: PlotSeries; point: PointResponse } {
  const l = { r1: 6, r2: 2, r3, r4: 5 };
  const grid = adaptiveGrid(l, { pixels, branches: ['open'] });
  const r = sweep(l, grid, { branch: 'open', method: 'closed-form' });
  const plot: PlotSeries = {
    theta2Deg: grid.map(radToDeg),
    open: { theta3: r.theta3, theta4: r.theta4 },
    crossed: null,
  };
  const theta2Rad = degToRad(45);
  const pose = solveClosedForm(l, theta2Rad, 'open');
  const point = {
    theta2Rad,
    pose: pose ? { theta3: pose.theta3, theta4: pose.theta4 } : null,
  } as unknown as PointResponse;
  return { plot, point };
}

async function run(steps: number, width: number, height: number): Promise<BenchRun> {
  const svgs = [document.getElementById('c3'), document.getElementById('c4')] as unknown as SVGSVGElement[];
  const cases = Array.from({ length: steps }, (_v, k) => fakeCycle(5 + 0.004 * (k % 50), width));
  const plots = makeAnglePlots(svgs, width, height);
  const msPerUpdate: number[] = [];
  for (const c of cases) {
    const t0 = performance.now();
    plots.update(plotDegrees(c.plot), c.point);
    msPerUpdate.push(performance.now() - t0);
    // One frame between steps, as between two worker answers.
    await new Promise((r) => requestAnimationFrame(r));
  }
  return { msPerUpdate };
}

(window as unknown as { runBench: typeof run }).runBench = run;
