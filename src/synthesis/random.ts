/**
 * Seeded pseudo-random numbers for the synthesis searches: no Math.random, so a search is a pure function of its
 * seed. mulberry32 (32-bit state, period 2^32) is plenty for sampling starts; splitmix32 mixes a seed with a
 * round or part index so that slices of a search can run anywhere (another worker) and draw the same numbers.
 */

/** A 32-bit hash of a seed and up to two indices (splitmix32 finaliser); any finite numbers, result in [0, 2^32). */
export function mixSeed(seed: number, a = 0, b = 0): number {
  let h = (Math.trunc(seed) ^ 0x9e3779b9) >>> 0;
  for (const k of [a, b]) {
    h = (h + Math.imul(Math.trunc(k) | 0, 0x85ebca6b) + 0x6a09e667) >>> 0;
    h ^= h >>> 16;
    h = Math.imul(h, 0x21f0aaad) >>> 0;
    h ^= h >>> 15;
    h = Math.imul(h, 0x735a2d97) >>> 0;
    h ^= h >>> 15;
  }
  return h >>> 0;
}

/** A generator of uniform numbers in [0, 1) from a 32-bit seed (mulberry32); the same seed gives the same stream. */
export function createRandom(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
