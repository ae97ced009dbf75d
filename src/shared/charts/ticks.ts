import { nice, tickStep, ticks } from 'd3-array';

/**
 * Tick values and nice domains of every chart, all from d3-array's ticks / nice / tickStep and
 * d3's log-tick lattice (1, 2 and 5 times each power of ten), so steps are 1, 2 or 5 times a power of ten (of a 30 degree unit on angle axes).
 * Tick counts come from pixel lengths, so a narrow chart gets fewer ticks instead of labels that collide.
 */

/** Degrees per unit of the coarse angle lattice: steps of 15, 30, 60, 150 degrees. */
const ANGLE_UNIT_DEG = 30;

/** m times 10^e, correctly rounded (10 ** -4 is not the double nearest 1e-4). */
export function dec(m: number, e: number): number {
  return Number(`${m}e${e}`);
}

/** Number of ticks for an axis lengthPx long with about spacingPx per tick (CSS pixels); at least 2. */
export function tickCount(lengthPx: number, spacingPx: number): number {
  return Math.max(2, Math.floor(lengthPx / spacingPx));
}

/**
 * The ticks of the largest count from start down to 1 whose centred labels keep gapPx apart along the
 * axis (positions from toPx, label widths from labelWidth, both in pixels); a single tick when even
 * count 1 collides. makeTicks is one of the d3-based tick functions here, at a given count.
 */
export function fittedTicks(
  makeTicks: (count: number) => number[],
  toPx: (v: number) => number,
  labelWidth: (v: number) => number,
  start: number,
  gapPx = 6,
): number[] {
  const fits = (t: number[]) =>
    t.every(
      (v, i) => i === 0 || Math.abs(toPx(v) - toPx(t[i - 1])) - (labelWidth(v) + labelWidth(t[i - 1])) / 2 >= gapPx,
    );
  for (let count = Math.max(1, start); count >= 1; count--) {
    const t = makeTicks(count);
    if (fits(t)) return t;
  }
  return makeTicks(1).slice(0, 1);
}

/** Removes the binary noise a unit change leaves (0.2 * 30 = 6.000000000000001 would print as such). */
function clean(v: number): number {
  return Number(v.toPrecision(12));
}

/** True when an angle axis over [lo, hi] degrees with about count ticks steps on the 30 degree lattice (15 degrees or more). */
function onAngleLattice(loDeg: number, hiDeg: number, count: number): boolean {
  return tickStep(loDeg / ANGLE_UNIT_DEG, hiDeg / ANGLE_UNIT_DEG, count) >= 0.5;
}

/**
 * About count angle ticks (degrees) in [loDeg, hiDeg]: d3 ticks in 30 degree units (15, 30, 60 or 150
 * degree steps) on a wide axis, plain d3 ticks in degrees (10, 5, 2, ... degree steps) on a narrow one.
 */
export function angleTicks(loDeg: number, hiDeg: number, count: number): number[] {
  if (!onAngleLattice(loDeg, hiDeg, count)) return ticks(loDeg, hiDeg, count);
  return ticks(loDeg / ANGLE_UNIT_DEG, hiDeg / ANGLE_UNIT_DEG, count).map((v) => clean(v * ANGLE_UNIT_DEG));
}

/** The nice domain of an angle axis and its ticks (degrees). */
export interface AngleAxis {
  domain: [number, number];
  ticks: number[];
}

/**
 * An angle axis over at least [loDeg, hiDeg]: the range widened by d3's nice to the step angleTicks would
 * use for about count ticks, within [-180, 180], and its ticks. Domain and ticks are computed in the same
 * unit (30 degrees or 1 degree), so the end ticks sit on the domain ends unless clamped at +-180.
 */
export function angleAxis(loDeg: number, hiDeg: number, count: number): AngleAxis {
  const unit = onAngleLattice(loDeg, hiDeg, count) ? ANGLE_UNIT_DEG : 1;
  const [a, b] = nice(loDeg / unit, hiDeg / unit, count).map((v) => clean(v * unit));
  const domain: [number, number] = [Math.max(-180, a), Math.min(180, b)];
  return { domain, ticks: ticks(domain[0] / unit, domain[1] / unit, count).map((v) => clean(v * unit)) };
}

/** About count whole-number ticks in [lo, hi] (d3 ticks with a step of at least 1); [lo] when hi <= lo. */
export function integerTicks(lo: number, hi: number, count: number): number[] {
  if (!(hi > lo)) return [Math.round(lo)];
  return ticks(lo, hi, Math.max(1, Math.min(count, hi - lo))).filter((v) => Number.isInteger(v));
}

/** [0, top]: d3's nice upper end for about count whole-number ticks from 0 to max (at least 1). */
export function niceCountDomain(max: number, count: number): [number, number] {
  const top = Math.max(1, Math.ceil(max));
  return [0, Math.max(top, nice(0, top, Math.max(1, Math.min(count, top)))[1])];
}

/** Decimal exponent of a power of ten (or of the decade v is in), robust to log10's last-bit error. */
function exponentOf(v: number): number {
  return Math.floor(Math.log10(v) + 1e-9);
}

/**
 * Powers of ten in [lo, hi] (lo, hi > 0): d3 ticks over the exponents with a whole step of 1, 2, 5 or
 * 10 decades, about count of them, on the lattice anchorExponent + k * step (default 10^0), so the ticks
 * do not shift as the data move.
 */
export function decadeTicks(lo: number, hi: number, count: number, anchorExponent = 0): number[] {
  const e0 = Math.ceil(Math.log10(lo) - 1e-9) - anchorExponent;
  const e1 = exponentOf(hi) - anchorExponent;
  if (e1 < e0) return [];
  const es = e1 === e0 ? [e0] : integerTicks(e0, e1, count);
  return es.map((e) => dec(1, e + anchorExponent));
}

/** 1, 2 and 5 times each power of ten in [lo, hi] (lo, hi > 0): the 1-2-5 subset of d3's log-scale ticks. */
export function oneTwoFiveTicks(lo: number, hi: number): number[] {
  const out: number[] = [];
  for (let e = Math.floor(Math.log10(lo)); e <= Math.ceil(Math.log10(hi)); e++) {
    for (const m of [1, 2, 5]) {
      const v = dec(m, e);
      if (v >= lo && v <= hi) out.push(v);
    }
  }
  return out;
}

/**
 * Ticks of a log axis over domain [lo, hi]: 1-2-5 ticks (oneTwoFiveTicks) when it spans under three
 * decades, otherwise decadeTicks with about count ticks anchored at 10^anchorExponent.
 */
export function logTicks(domain: readonly [number, number], count: number, anchorExponent = 0): number[] {
  const [lo, hi] = domain;
  if (Math.log10(hi / lo) < 3) return oneTwoFiveTicks(lo, hi);
  return decadeTicks(lo, hi, count, anchorExponent);
}

/** [lo, hi] (lo, hi > 0) widened to whole decades, as d3's scaleLog().nice(). */
export function niceLogDomain(lo: number, hi: number): [number, number] {
  return [dec(1, Math.floor(Math.log10(lo))), dec(1, Math.ceil(Math.log10(hi)))];
}

/** [lo, hi] (lo, hi > 0) widened to the nearest 1, 2 or 5 times a power of ten outside it, on d3's log tick lattice. */
export function niceOneTwoFiveDomain(lo: number, hi: number): [number, number] {
  const [a, b] = niceLogDomain(lo, hi);
  const lattice = oneTwoFiveTicks(a, b);
  const below = lattice.filter((v) => v <= lo * (1 + 1e-12));
  const above = lattice.filter((v) => v >= hi * (1 - 1e-12));
  return [below.length ? below[below.length - 1] : a, above.length ? above[0] : b];
}
