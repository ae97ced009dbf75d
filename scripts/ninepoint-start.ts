/**
 * Computes the nine-point start system by monodromy and writes src/synthesis/ninePoint/startData.ts: one generic
 * complex parameter point p0 and one root of each orbit of the order-6 group (relabelling × Roberts cognates).
 * From a seeded random root, every known root is tracked around random triangles p0 → p1 → p2 → p0; a root not yet
 * known (compared by orbit key) joins. Stops by its own rule: STALL full loops in a row that add nothing. Reports
 * the count reached; it does not know the expected 1442.
 * Run: npm run build:ninepoint-start   (SEED, STALL and MAX_LOOPS from the environment; defaults 1, 3, 200)
 */
import { writeFileSync } from 'node:fs';
import { format, resolveConfig } from 'prettier';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { NV, isDegenerate } from '../src/synthesis/ninePoint/equations';
import { orbitKey, sameKey } from '../src/synthesis/ninePoint/group';
import { randomComplex, seedRoot } from '../src/synthesis/ninePoint/startRoot';
import { Tracker } from '../src/synthesis/ninePoint/tracker';
import { encodeStart } from '../src/synthesis/ninePoint/startCodec';
import { createRandom } from '../src/synthesis/random';

const SEED = Number(process.env.SEED ?? 1);
const STALL = Number(process.env.STALL ?? 3);
const MAX_LOOPS = Number(process.env.MAX_LOOPS ?? 200);
const here = dirname(fileURLToPath(import.meta.url));
const out = resolve(here, '../src/synthesis/ninePoint/startData.ts');

const rand = createRandom(SEED);
let seed = seedRoot(rand);
while (!seed) seed = seedRoot(rand);
const p0 = seed.p;
const roots: Float64Array[] = [seed.z];
const keys: Float64Array[] = [orbitKey(seed.z)];
const tracker = new Tracker();
const t0 = performance.now();
let stall = 0;
let tracked = 0;
let failed = 0;
let degenerate = 0;

/** Writes the generated module formatted as the repository's Prettier would. */
async function write(text: string): Promise<void> {
  const config = (await resolveConfig(out)) ?? {};
  writeFileSync(out, await format(text, { ...config, filepath: out }));
}

function known(k: Float64Array): boolean {
  for (const q of keys) if (sameKey(q, k, 1e-7)) return true;
  return false;
}

for (let loop = 1; loop <= MAX_LOOPS && stall < STALL; loop++) {
  const p1 = new Float64Array(4 * NV);
  const p2 = new Float64Array(4 * NV);
  randomComplex(rand, p1);
  randomComplex(rand, p2);
  const g = new Float64Array(6);
  randomComplex(rand, g);
  const legs: [Float64Array, Float64Array][] = [
    [p0, p1],
    [p1, p2],
    [p2, p0],
  ];
  const before = roots.length;
  const n = roots.length;
  for (let r = 0; r < n; r++) {
    const z = roots[r].slice();
    let ok = true;
    for (let leg = 0; leg < 3 && ok; leg++) {
      tracker.setSegment(legs[leg][0], legs[leg][1], g[2 * leg], g[2 * leg + 1]);
      tracked++;
      // Any root reached is a root: a looser corrector only risks jumping to another path, harmless here.
      ok = tracker.track(z, { tol: 1e-6 }).status === 'finished';
    }
    if (!ok) {
      failed++;
      continue;
    }
    // A degenerate root (a spurious one of the elimination, see isDegenerate) is no start solution.
    if (isDegenerate(z, p0)) {
      degenerate++;
      continue;
    }
    const k = orbitKey(z);
    if (!Number.isFinite(k[0])) continue;
    if (!known(k)) {
      roots.push(z);
      keys.push(k);
    }
  }
  const added = roots.length - before;
  stall = added === 0 ? stall + 1 : 0;
  const s = ((performance.now() - t0) / 1000).toFixed(1);
  console.log(
    `loop ${loop}: ${roots.length} orbits (+${added}), ${tracked} segments, ${failed} failed loops, ${degenerate} degenerate ends, ${s} s`,
  );
  // Written every loop, so an interrupted run still leaves what it reached, saying so.
  const note = `Seed ${SEED}: ${roots.length} orbits (${6 * roots.length} roots) after loop ${loop}, ${stall} loops without a new one.`;
  await write(encodeStart(p0, roots, note));
}

const why = stall >= STALL ? `${STALL} loops without a new orbit` : `the loop limit ${MAX_LOOPS}`;
const text = encodeStart(
  p0,
  roots,
  `Seed ${SEED}: ${roots.length} orbits (${6 * roots.length} roots), stopped by ${why}.`,
);
await write(text);
console.log(
  `stopped by ${why}: ${roots.length} orbits = ${6 * roots.length} roots; wrote ${out} (${text.length} bytes)`,
);
