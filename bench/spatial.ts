/**
 * Spatial four-bars (src/spatial): poses per second of solveSpherical and solveRSSR (one pose with rates and, for the
 * spherical preset, its coupler point: validation, plan and objects included, as the page calls them), of sweepSpatial
 * over a turn (typed columns, no objects per pose) and of the CSV rows, on the presets of issue 32. Medians of
 * interleaved passes (src/study's medianTime). Writes bench/results/spatial.json.
 * Run: npm run bench (after the solver's rows), or vite-node bench/spatial.ts   (BENCH_QUICK=1 for a shorter run)
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { cpus } from 'node:os';
import { medianTime } from '../src/study/workPrecision';
import { SPATIAL_PRESETS, solveRSSR, solveSpherical, spatialCsvRows, sweepSpatial } from '../src/spatial';
import type { RSSRLinkage, SpatialModel, SphericalLinkage } from '../src/spatial';

const here = dirname(fileURLToPath(import.meta.url));
const QUICK = process.env.BENCH_QUICK === '1';
const MIN_MS = QUICK ? 20 : 150;
const PASSES = 3;

interface Row {
  name: string;
  preset: string;
  posesPerCall: number;
  posesPerSecond: number;
}

const model = (id: string): SpatialModel => SPATIAL_PRESETS.find((p) => p.id === id)!.model;
const sph = model('sph-crank-rocker').linkage as SphericalLinkage;
const rssr = model('rssr-skew').linkage as RSSRLinkage;
const ANGLES = Array.from({ length: 360 }, (_, i) => (i * Math.PI) / 180);
const input = { omega2: 1, alpha2: 0 };
let sink = 0;

const cases: Array<{ name: string; preset: string; poses: number; run: () => void }> = [
  {
    name: 'solveSpherical (pose, rates, coupler point)',
    preset: 'sph-crank-rocker',
    poses: ANGLES.length,
    run: () => {
      for (const t of ANGLES) sink += solveSpherical(sph, t, 'open', input)?.theta4 ?? 0;
    },
  },
  {
    name: 'solveRSSR (pose, rates)',
    preset: 'rssr-skew',
    poses: ANGLES.length,
    run: () => {
      for (const t of ANGLES) sink += solveRSSR(rssr, t, 'open', input)?.theta4 ?? 0;
    },
  },
  {
    name: 'sweepSpatial spherical, 360 steps (+ coupler point)',
    preset: 'sph-crank-rocker',
    poses: 361,
    run: () => {
      sink += sweepSpatial(model('sph-crank-rocker'), 'open').theta4[7];
    },
  },
  {
    name: 'sweepSpatial RSSR, 360 steps',
    preset: 'rssr-skew',
    poses: 361,
    run: () => {
      sink += sweepSpatial(model('rssr-skew'), 'open').theta4[7];
    },
  },
  {
    name: 'sweepSpatial spherical, 100000 steps',
    preset: 'sph-crank-rocker',
    poses: 100001,
    run: () => {
      sink += sweepSpatial(model('sph-crank-rocker'), 'open', { steps: 100000 }).theta4[7];
    },
  },
  {
    name: 'spatialCsvRows RSSR, 1 degree',
    preset: 'rssr-skew',
    poses: 361,
    run: () => {
      sink += spatialCsvRows(model('rssr-skew'), 'open').rows.length;
    },
  },
];

const rows: Row[] = cases.map((c) => ({ name: c.name, preset: c.preset, posesPerCall: c.poses, posesPerSecond: 0 }));
for (let pass = 0; pass < PASSES; pass++) {
  cases.forEach((c, k) => {
    const ms = medianTime(c.run, () => performance.now(), MIN_MS / PASSES);
    rows[k].posesPerSecond = Math.max(rows[k].posesPerSecond, (c.poses * 1000) / ms);
  });
}

console.log(`\n== Spatial four-bars (src/spatial), poses per second, best of ${PASSES} interleaved passes`);
for (const r of rows) {
  console.log(
    `${r.name.padEnd(52)} ${r.preset.padEnd(17)} ${(r.posesPerSecond / 1e6).toFixed(2).padStart(7)} M poses/s`,
  );
}
const outDir = resolve(here, 'results');
mkdirSync(outDir, { recursive: true });
writeFileSync(
  resolve(outDir, 'spatial.json'),
  JSON.stringify(
    {
      date: new Date().toISOString(),
      node: process.version,
      cpu: cpus()[0]?.model,
      quick: QUICK,
      rows,
      sink: sink !== 0,
    },
    null,
    2,
  ) + '\n',
);
console.log('wrote bench/results/spatial.json');
