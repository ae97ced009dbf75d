/**
 * The nine-point row of bench:synthesis: Problem 3 of Wampler, Morgan and Sommese (1992) solved completely on one core
 * (ninePointSynthesis over every shipped start path), with the real classes found, the paths, the time and paths/s.
 * Also runs alone: PRINT_NINE_POINT=1 npx vite-node bench/synthesisNinePoint.ts
 */
import { ninePointSynthesis } from '../src/synthesis';

/** Problem 3's nine points (WMS 1992; the alphaCertified data of Hauenstein and Sottile). */
export const PROBLEM_3 = [
  [0.25, 0.0],
  [0.52, 0.1],
  [0.8, 0.7],
  [1.2, 1.0],
  [1.4, 1.3],
  [1.1, 1.48],
  [0.7, 1.4],
  [0.2, 1.0],
  [0.02, 0.4],
].map(([x, y]) => ({ x, y }));

export interface NinePointRow {
  case: string;
  classes: number;
  grashof: number;
  defectFree: number;
  paths: { total: number; finished: number; failed: number };
  ms: number;
  pathsPerS: number;
}

/** Solves Problem 3 once (start system loaded and polished before the clock starts). */
export async function ninePointRow(): Promise<NinePointRow> {
  await ninePointSynthesis(PROBLEM_3, { paths: { start: 0, end: 1 } });
  const t0 = performance.now();
  const r = await ninePointSynthesis(PROBLEM_3);
  const ms = performance.now() - t0;
  return {
    case: 'WMS Problem 3',
    classes: r.classes.length,
    grashof: r.classes.filter((c) => c.grashof).length,
    defectFree: r.classes.filter((c) => c.defects.length === 0).length,
    paths: r.paths,
    ms,
    pathsPerS: r.paths.total / (ms / 1000),
  };
}

/** The row as a Markdown table. */
export function ninePointTable(r: NinePointRow): string {
  return [
    '| case | real classes | Grashof | no defect | paths (finished / failed / total) | time s | paths/s |',
    '|---|---|---|---|---|---|---|',
    `| ${r.case} | ${r.classes} | ${r.grashof} | ${r.defectFree} | ${r.paths.finished} / ${r.paths.failed} / ${r.paths.total} | ${(r.ms / 1000).toFixed(1)} | ${r.pathsPerS.toFixed(1)} |`,
  ].join('\n');
}

// vite-node hides the script from process.argv, so a standalone run asks for the row by environment.
if (process.env.PRINT_NINE_POINT === '1') {
  console.log(ninePointTable(await ninePointRow()));
}
