/**
 * The nine-point row of bench:synthesis: Problem 3 of Wampler, Morgan and Sommese (1992) solved completely on one core
 * (ninePointSynthesis over every shipped start path), with the real classes found, the paths, the time and paths/s.
 * Also runs alone: PRINT_NINE_POINT=1 npx vite-node bench/synthesisNinePoint.ts
 */
import { WMS_PROBLEM_3 as PROBLEM_3 } from '../src/features/synthesis/ninePoint/wmsProblem3';
import { ninePointSynthesis } from '../src/synthesis';

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
