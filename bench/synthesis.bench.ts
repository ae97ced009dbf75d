/**
 * Path-synthesis benchmark: the literature's standard problems and exact problems (tests/synthesis/benchmarkCases.ts),
 * each run with 5 seeds and a 10 s budget on one core. Prints, per case, Σd² (median and spread over the seeds),
 * the best published Σd², the time and the evaluations (median and spread), then the closed-form synthesis rows of
 * bench/synthesisClosedForms.ts when that file exists, then the pool's speed-up (bench/synthesisPool.ts: a fixed number of
 * rounds on 1 and on 2 … cores − 1 processes), then the nine-point row (bench/synthesisNinePoint.ts: WMS Problem 3 solved
 * completely on one core, classes, paths and paths/s); writes bench/results/synthesis.json and synthesis-table.md.
 * The path table's columns (issue 34 item 6): the published claim (the best Σd² a source states, or "none found"),
 * the published design's Σd² recomputed from its parameters (tests/synthesis/literatureDesign.ts: the better branch
 * when the paper does not say, and the case's constraints it breaks), ours (best and median over the seeds), whether
 * every seed reached the recomputed value (else the claim; "exact" where the seeds fit to rounding, which no
 * published value can beat), and the time each run took to reach its final best (the run goes on until the budget).
 * Run: npm run bench:synthesis   (BENCH_QUICK=1: 2 seeds, 3 s budget; BENCH_PATH_ONLY=1: the path table alone, which
 * every run also writes to bench/results/synthesis-path.md)
 */
import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { POLISH_SHARE, mergePathCandidates, pathSynthesisPart } from '../src/synthesis';
import { BENCHMARK_CASES, targetSize } from '../tests/synthesis/benchmarkCases';
import { recomputePublished, reproducesClaim } from '../tests/synthesis/literatureDesign';
import type { RecomputedDesign } from '../tests/synthesis/literatureDesign';
import { poolRows } from './synthesisPool';
import { ninePointRow, ninePointTable } from './synthesisNinePoint';

const here = dirname(fileURLToPath(import.meta.url));
const QUICK = process.env.BENCH_QUICK === '1';
const SEEDS = QUICK ? [1, 2] : [1, 2, 3, 4, 5];
const BUDGET_MS = QUICK ? 3000 : 10000;
const PATH_ONLY = process.env.BENCH_PATH_ONLY === '1';

interface Row {
  case: string;
  title: string;
  n: number;
  timing: string;
  f: number[];
  fOverSize2: number[];
  exact: boolean;
  /** The best Σd² the source states, or null. */
  claim: number | null;
  /** The published design's Σd² recomputed from its parameters, when a design is recorded. */
  recomputed: RecomputedDesign | null;
  publishedSource: string;
  size2: number;
  ms: number[];
  /** Time from the start to the first report of the run's final best (within 1e-9 relative), ms. */
  bestMs: number[];
  evaluations: number[];
  solutions: number[];
}

const median = (v: number[]) => {
  const s = [...v].sort((a, b) => a - b);
  const h = s.length >> 1;
  return s.length % 2 ? s[h] : (s[h - 1] + s[h]) / 2;
};
const spread = (v: number[], fmt: (x: number) => string) => `${fmt(Math.min(...v))} … ${fmt(Math.max(...v))}`;
const sci = (x: number) => (x === 0 ? '0' : x.toExponential(3));
const ms = (x: number) => `${Math.round(x)}`;
/** Seven significant digits: enough to compare with a published value such as 1.21622. */
const fine = (x: number) => (x === 0 ? '0' : x.toExponential(6));

async function runCase(c: (typeof BENCHMARK_CASES)[number]): Promise<Row> {
  const row: Row = {
    case: c.id,
    title: c.title,
    n: c.task.targets.length,
    timing: c.task.timing.kind,
    f: [],
    fOverSize2: [],
    exact: c.exact,
    claim: c.published.claim,
    recomputed: c.published.design ? recomputePublished(c.published.design, c.task) : null,
    publishedSource: c.published.source,
    size2: targetSize(c.task.targets) ** 2,
    ms: [],
    bestMs: [],
    evaluations: [],
    solutions: [],
  };
  const size = targetSize(c.task.targets);
  for (const seed of SEEDS) {
    const t0 = Date.now();
    // What pathSynthesis does, with the evaluation count kept.
    const reports: [number, number][] = [];
    // As pathSynthesis does: the global stage stops at (1 − POLISH_SHARE) of the budget, the polish has the rest.
    const part = await pathSynthesisPart(c.task, {
      seed,
      budgetMs: (1 - POLISH_SHARE) * BUDGET_MS,
      onProgress: (p) => reports.push([Date.now() - t0, p.best]),
    });
    const sols = mergePathCandidates(c.task, [part.candidates], Math.max(Date.now(), t0 + BUDGET_MS) + 200);
    const elapsed = Date.now() - t0;
    const f = sols[0]?.error ?? Infinity;
    // The merge's polish may improve on the part's best a little: the run reached its best when the part first
    // reported a value within 1e-9 of the final one, or at the end.
    const size2 = size * size;
    const hit = reports.find(([, b]) => b <= f * (1 + 1e-9) + 1e-20 * size2);
    row.bestMs.push(hit ? hit[0] : elapsed);
    row.f.push(f);
    row.fOverSize2.push(f / (size * size));
    row.ms.push(elapsed);
    row.evaluations.push(part.evaluations);
    row.solutions.push(sols.length);
    console.error(
      `${c.id} seed ${seed}: f ${sci(f)} in ${elapsed} ms (best at ${row.bestMs.at(-1)} ms), ${sols.length} answers`,
    );
  }
  return row;
}

/** The value ours is held to: the published design's recomputed Σd² where it assembles, else the claim. */
const publishedValue = (r: Row): number | null =>
  r.recomputed && Number.isFinite(r.recomputed.f) ? r.recomputed.f : r.claim;
/** At or below the value (with the exact criterion's slack, 1e-20 size², for a published 0). */
const reaches = (r: Row, f: number, value: number) => f <= value + 1e-20 * r.size2;

/** Whether every seed reached the published value, or fit an exact case to rounding (which nothing can beat). */
function verdict(r: Row): string {
  const value = publishedValue(r);
  if (value !== null) {
    const all = r.f.every((f) => reaches(r, f, value));
    const by = value - Math.max(...r.f);
    const v = all ? (by > 1e-20 * r.size2 ? `yes (by ${sci(by)})` : 'yes') : `no (worst seed ${sci(-by)} above)`;
    return r.recomputed?.violations.length ? `${v}; the published design breaks the case` : v;
  }
  if (r.exact) return r.f.every((f) => f <= 1e-20 * r.size2) ? 'exact fit: none can be lower' : 'no';
  return '—';
}

/** The published design's recomputed Σd², its branch and what of the case it breaks; or why there is none. */
function recomputedCell(r: Row): string {
  const d = r.recomputed;
  if (!d)
    return r.publishedSource === 'by construction' || r.publishedSource === 'not a literature case'
      ? '—'
      : 'no design found';
  const value = Number.isFinite(d.f) ? fine(d.f) : 'does not assemble';
  const claim =
    r.claim === null || !Number.isFinite(d.f)
      ? ''
      : reproducesClaim(r.claim, d.f)
        ? '; reproduces the claim'
        : '; does not reproduce the claim';
  return `${value} (${d.branch}${claim}${d.violations.length ? `; breaks: ${d.violations.join(', ')}` : ''})`;
}

/** The published claim and its source, or what was searched when nothing was found. */
function claimCell(r: Row): string {
  if (r.claim !== null) return `${r.claim === 0 ? '0' : r.claim.toPrecision(6)} (${r.publishedSource})`;
  if (r.publishedSource === 'not a literature case') return '— (not a literature case)';
  return `none found (searched: ${r.publishedSource})`;
}

function table(rows: Row[]): string {
  const head =
    '| case | n | timing | published claim Σd² | published design, Σd² recomputed | ours: best | ours: median | ours: spread | f / size² median | every seed ≤ published | time to best ms median | time to best spread | evaluations median |';
  const sep = '|---|---|---|---|---|---|---|---|---|---|---|---|---|';
  const body = rows.map((r) =>
    [
      r.case,
      r.n,
      r.timing,
      claimCell(r),
      recomputedCell(r),
      fine(Math.min(...r.f)),
      fine(median(r.f)),
      spread(r.f, sci),
      sci(median(r.fOverSize2)),
      verdict(r),
      ms(median(r.bestMs)),
      spread(r.bestMs, ms),
      Math.round(median(r.evaluations)),
    ].join(' | '),
  );
  return [head, sep, ...body.map((b) => `| ${b} |`)].join('\n');
}

interface ClosedFormRow {
  case: string;
  medianMs: number;
  spreadMs: string;
}

/** The other synthesis bench's rows (bench/synthesisClosedForms.ts), when that file exists. */
async function closedForms(): Promise<ClosedFormRow[] | null> {
  const file = resolve(here, 'synthesisClosedForms.ts');
  if (!existsSync(file)) return null;
  const mod = (await import(/* @vite-ignore */ pathToFileURL(file).href)) as { closedFormRows(): ClosedFormRow[] };
  return mod.closedFormRows();
}

const rows: Row[] = [];
for (const c of BENCHMARK_CASES) rows.push(await runCase(c));
const pathTable = table(rows);
console.log(`\nPath synthesis, ${SEEDS.length} seeds, budget ${BUDGET_MS} ms per run (one core):\n`);
console.log(pathTable);
// The path table alone as well, so a full run and a BENCH_PATH_ONLY run leave the same file current.
mkdirSync(resolve(here, 'results'), { recursive: true });
writeFileSync(
  resolve(here, 'results', 'synthesis-path.md'),
  `# bench:synthesis (path table)\n\nPath synthesis, ${SEEDS.length} seeds, budget ${BUDGET_MS} ms per run (one core).\n\n${pathTable}\n`,
);
if (PATH_ONLY) process.exit(0);
const cf = await closedForms();
let cfTable = '';
if (cf) {
  cfTable = [
    '| case | median ms | spread ms |',
    '|---|---|---|',
    ...cf.map((r) => `| ${r.case} | ${r.medianMs.toPrecision(3)} | ${r.spreadMs} |`),
  ].join('\n');
  console.log('\nClosed-form synthesis:\n');
  console.log(cfTable);
} else console.log('\n(bench/synthesisClosedForms.ts not found: no closed-form table)');
/** Rounds of the pool rows: a fixed count, so every pool size does the same work and must give the same answers. */
const POOL_ROUNDS = QUICK ? 24 : 96;
const pool = await poolRows(['kunjur-18-step', 'ellipse-10'], POOL_ROUNDS);
const poolTable = [
  '| case | rounds | processes | wall ms | speed-up | best f | same best f as 1 |',
  '|---|---|---|---|---|---|---|',
  ...pool.map(
    (r) =>
      `| ${r.case} | ${r.rounds} | ${r.parts} | ${ms(r.ms)} | ${r.speedup.toFixed(2)} | ${sci(r.bestF)} | ${r.sameBestAsOne ? 'yes' : 'no'} |`,
  ),
].join('\n');
console.log('\nThe pool (pathSynthesisPart in parallel processes, then mergePathCandidates):\n');
console.log(poolTable);
const nine = await ninePointRow();
const nineTable = ninePointTable(nine);
console.log('\nNine-point synthesis (every four-bar through nine points, one core):\n');
console.log(nineTable);
const out = resolve(here, 'results');
mkdirSync(out, { recursive: true });
writeFileSync(
  resolve(out, 'synthesis.json'),
  JSON.stringify(
    {
      date: new Date().toISOString(),
      quick: QUICK,
      seeds: SEEDS,
      budgetMs: BUDGET_MS,
      path: rows,
      closedForms: cf,
      pool,
      ninePoint: nine,
    },
    null,
    2,
  ) + '\n',
);
writeFileSync(
  resolve(out, 'synthesis-table.md'),
  `# bench:synthesis\n\nPath synthesis, ${SEEDS.length} seeds, budget ${BUDGET_MS} ms per run (one core).\n\n${pathTable}\n` +
    (cfTable ? `\nClosed-form synthesis:\n\n${cfTable}\n` : '') +
    `\nThe pool (${POOL_ROUNDS} rounds dealt to parts in parallel processes, then merged):\n\n${poolTable}\n` +
    `\nNine-point synthesis (every four-bar through nine points, one core):\n\n${nineTable}\n`,
);
