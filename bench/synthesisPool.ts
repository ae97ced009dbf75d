/**
 * The synthesis page's pool, measured: a case's global stage with a fixed number of rounds dealt to k parts, each in
 * its own node process (as each worker of the pool runs its part), for k = 1 and k = 2 … cores − 1 (at least 2), then
 * merged. Wall time from the first spawn to the last answer (process start-up included), the speed-up against k = 1,
 * and whether the best answer's Σd² equals k = 1's (to 1e-9 relative). The lower-ranked answers may differ: each
 * part keeps its own best candidates, so k parts hand the merge a different (larger) set than one part does.
 */
import { execFile } from 'node:child_process';
import { availableParallelism } from 'node:os';
import { fileURLToPath } from 'node:url';
import { mergePathCandidates } from '../src/synthesis';
import type { PathSynthesisPartResult } from '../src/synthesis';
import { BENCHMARK_CASES } from '../tests/synthesis/benchmarkCases';
import { bundleForNode } from './nodeBundle';

/** One pool row: the case, the pool size, its wall time, speed-up against one part, and the answers' agreement. */
export interface PoolRow {
  case: string;
  rounds: number;
  parts: number;
  ms: number;
  speedup: number;
  bestF: number;
  sameBestAsOne: boolean;
}

function runPart(file: string, args: string[]): Promise<PathSynthesisPartResult> {
  return new Promise((resolve, reject) =>
    execFile(process.execPath, [file, ...args], { maxBuffer: 64 * 1024 * 1024 }, (err, out) => {
      if (err) reject(err);
      else resolve(JSON.parse(out.trim().split('\n').pop()!) as PathSynthesisPartResult);
    }),
  );
}

/** Runs the pool rows for the given cases (ids) with rounds rounds each, seed 1. */
export async function poolRows(ids: string[], rounds: number): Promise<PoolRow[]> {
  const bundle = await bundleForNode(fileURLToPath(new URL('./synthesisPoolChild.ts', import.meta.url)));
  const sizes = [1, ...Array.from({ length: Math.max(2, availableParallelism() - 1) - 1 }, (_, i) => i + 2)];
  const rows: PoolRow[] = [];
  try {
    for (const id of ids) {
      const c = BENCHMARK_CASES.find((x) => x.id === id)!;
      let one: { ms: number; bestF: number } | null = null;
      for (const parts of sizes) {
        const t0 = performance.now();
        const results = await Promise.all(
          Array.from({ length: parts }, (_, part) =>
            runPart(bundle.file, [JSON.stringify(c.task), '1', String(part), String(parts), String(rounds)]),
          ),
        );
        const merged = mergePathCandidates(
          c.task,
          results.map((r) => r.candidates),
        );
        const ms = performance.now() - t0;
        const bestF = merged[0]?.error ?? Infinity;
        one ??= { ms, bestF };
        rows.push({
          case: id,
          rounds,
          parts,
          ms,
          speedup: one.ms / ms,
          bestF,
          sameBestAsOne: Math.abs(bestF - one.bestF) <= 1e-9 * Math.max(bestF, one.bestF),
        });
        console.error(`${id} rounds ${rounds} on ${parts} process(es): ${Math.round(ms)} ms`);
      }
    }
  } finally {
    bundle.dispose();
  }
  return rows;
}
