/**
 * Template linkages as data: each a MechanismSpec in a drawn configuration, built from its published dimensions
 * with circle intersections in double precision (the drawn pose defines every length, so the spec closes exactly
 * whatever the rounding). Sources are cited in docs/mechanism.md.
 */
import type { JointSpec, MechanismSpec, TracerSpec } from './types';

/** A named template: the spec, the input range that makes sense (radians or length), and a one-line note. */
export interface MechanismTemplate {
  name: string;
  spec: MechanismSpec;
  /** A full turn for a crank, the swing for a rocker or a slider's stroke; 0 = as drawn. */
  inputRange: [number, number];
  note: string;
}

type Pt = [number, number];

/** The intersection of circle (p, rp) and circle (q, rq) left of p → q (side +1) or right (side -1). */
function dyad(p: Pt, rp: number, q: Pt, rq: number, side: 1 | -1): Pt {
  const dx = q[0] - p[0];
  const dy = q[1] - p[1];
  const d2 = dx * dx + dy * dy;
  const d = Math.sqrt(d2);
  const a = (rp * rp - rq * rq + d2) / (2 * d);
  const h = Math.sqrt(Math.max(0, rp * rp - a * a));
  return [p[0] + (a * dx - side * h * dy) / d, p[1] + (a * dy + side * h * dx) / d];
}

/** The circle intersection whose coordinate `axis` (0 x, 1 y) is the larger (+1) or smaller (-1). */
function dyadBy(p: Pt, rp: number, q: Pt, rq: number, axis: 0 | 1, larger: 1 | -1): Pt {
  const u = dyad(p, rp, q, rq, 1);
  const v = dyad(p, rp, q, rq, -1);
  return (u[axis] - v[axis]) * larger > 0 ? u : v;
}

const polar = (p: Pt, r: number, angle: number): Pt => [p[0] + r * Math.cos(angle), p[1] + r * Math.sin(angle)];

const R = (id: string, a: string, b: string, p: Pt): JointSpec => ({ id, kind: 'R', links: [a, b], x: p[0], y: p[1] });
const P = (id: string, block: string, guide: string, p: Pt, angle: number): JointSpec => ({
  id,
  kind: 'P',
  links: [block, guide],
  x: p[0],
  y: p[1],
  angle,
});
const T = (id: string, link: string, p: Pt): TracerSpec => ({ id, link, x: p[0], y: p[1] });

const FULL_TURN: [number, number] = [0, 2 * Math.acos(-1)];

/** Four-bar r1 ground, r2 crank, r3 coupler, r4 rocker drawn at crank angle theta2, open branch, with a coupler point. */
export function fourBarSpec(r1: number, r2: number, r3: number, r4: number, theta2 = 0): MechanismSpec {
  const o2: Pt = [0, 0];
  const o4: Pt = [r1, 0];
  const a = polar(o2, r2, theta2);
  const b = dyad(a, r3, o4, r4, 1);
  return {
    links: ['ground', 'crank', 'coupler', 'rocker'],
    joints: [
      R('O2', 'ground', 'crank', o2),
      R('A', 'crank', 'coupler', a),
      R('B', 'coupler', 'rocker', b),
      R('O4', 'rocker', 'ground', o4),
    ],
    points: [T('P', 'coupler', [(a[0] + b[0]) / 2 + (a[1] - b[1]) / 2, (a[1] + b[1]) / 2 + (b[0] - a[0]) / 2])],
    input: { joint: 'O2' },
  };
}

/** Offset slider-crank: crank r from O2, coupler l, slider on the line y = e (along +x), drawn at crank angle 0. */
export function sliderCrankSpec(r: number, l: number, e: number): MechanismSpec {
  const a: Pt = [r, 0];
  const b: Pt = [r + Math.sqrt((l - e) * (l + e)), e];
  return {
    links: ['ground', 'crank', 'coupler', 'slider'],
    joints: [
      R('O2', 'ground', 'crank', [0, 0]),
      R('A', 'crank', 'coupler', a),
      R('B', 'coupler', 'slider', b),
      P('S', 'slider', 'ground', b, 0),
    ],
    input: { joint: 'O2' },
  };
}

/**
 * Inverted slider-crank (crank-shaper quick return): crank r about O2 = (0, 0), its pin A in a block sliding on
 * a slotted rocker about O4 = (0, -d), drawn at crank angle theta2; the rocker carries a tracer at length reach.
 */
export function invertedSliderCrankSpec(r: number, d: number, reach: number, theta2 = 0): MechanismSpec {
  const o4: Pt = [0, -d];
  const a = polar([0, 0], r, theta2);
  const dir = Math.atan2(a[1] - o4[1], a[0] - o4[0]);
  return {
    links: ['ground', 'crank', 'block', 'rocker'],
    joints: [
      R('O2', 'ground', 'crank', [0, 0]),
      R('A', 'crank', 'block', a),
      P('S', 'block', 'rocker', a, dir),
      R('O4', 'rocker', 'ground', o4),
    ],
    points: [T('Tip', 'rocker', polar(o4, reach, dir))],
    input: { joint: 'O2' },
  };
}

/** Whitworth quick return: crank r about O2, its block in a slotted link turning fully about O4 (d below O2, d < r), which drives a ram along y = -d through a connecting rod. */
export function whitworthSpec(r = 2, d = 1, arm = 1.5, rod = 5): MechanismSpec {
  const o4: Pt = [0, -d];
  const a: Pt = [0, r];
  const c: Pt = [0, -d - arm];
  const e: Pt = [Math.sqrt((rod - arm) * (rod + arm)), -d];
  return {
    links: ['ground', 'crank', 'block', 'slotted', 'rod', 'ram'],
    joints: [
      R('O2', 'ground', 'crank', [0, 0]),
      R('A', 'crank', 'block', a),
      P('S', 'block', 'slotted', a, Math.acos(-1) / 2),
      R('O4', 'slotted', 'ground', o4),
      R('C', 'slotted', 'rod', c),
      R('E', 'rod', 'ram', e),
      P('Ram', 'ram', 'ground', e, 0),
    ],
    input: { joint: 'O2' },
  };
}

/** Scotch yoke: crank r about O2, its pin in a block sliding in the yoke's vertical slot; the yoke slides along x. */
export function scotchYokeSpec(r = 2, theta2 = 1): MechanismSpec {
  const a = polar([0, 0], r, theta2);
  const y: Pt = [a[0], 0];
  return {
    links: ['ground', 'crank', 'block', 'yoke'],
    joints: [
      R('O2', 'ground', 'crank', [0, 0]),
      R('A', 'crank', 'block', a),
      P('Slot', 'block', 'yoke', a, Math.acos(-1) / 2),
      P('Guide', 'yoke', 'ground', y, 0),
    ],
    input: { joint: 'O2' },
  };
}

/** A slider-crank driven by its piston (input on the P joint: length), as a press or a pump seen backwards. */
export function pistonDrivenSpec(r = 2, l = 5, theta2 = 1.2): MechanismSpec {
  const a = polar([0, 0], r, theta2);
  const b: Pt = [a[0] + Math.sqrt((l - a[1]) * (l + a[1])), 0];
  return {
    links: ['ground', 'crank', 'rod', 'piston'],
    joints: [
      R('O2', 'ground', 'crank', [0, 0]),
      R('A', 'crank', 'rod', a),
      R('B', 'rod', 'piston', b),
      P('Bore', 'piston', 'ground', b, 0),
    ],
    input: { joint: 'Bore' },
  };
}

/** Watt I: a four-bar whose coupler and rocker (both ternary, sharing B) are joined by a two-link chain C–D–E. */
export function wattISpec(theta2 = 0.5): MechanismSpec {
  const o2: Pt = [0, 0];
  const o4: Pt = [6, 0];
  const a = polar(o2, 2, theta2);
  const b = dyad(a, 5, o4, 5, 1);
  const c = polar(a, 4, Math.atan2(b[1] - a[1], b[0] - a[0]) + 1.0);
  const e = polar(o4, 3, Math.atan2(b[1] - o4[1], b[0] - o4[0]) - 0.6);
  const d = dyadBy(c, 4, e, 3.5, 1, 1);
  return {
    links: ['ground', 'crank', 'coupler', 'rocker', 'link5', 'link6'],
    joints: [
      R('O2', 'ground', 'crank', o2),
      R('A', 'crank', 'coupler', a),
      R('B', 'coupler', 'rocker', b),
      R('O4', 'rocker', 'ground', o4),
      R('C', 'coupler', 'link5', c),
      R('D', 'link5', 'link6', d),
      R('E', 'link6', 'rocker', e),
    ],
    points: [T('P', 'link5', [(c[0] + d[0]) / 2, (c[1] + d[1]) / 2])],
    input: { joint: 'O2' },
  };
}

/** Watt II: two four-bars in series, the first's rocker (ternary, about O4) the second's crank. */
export function wattIISpec(theta2 = 0.5): MechanismSpec {
  const o2: Pt = [0, 0];
  const o4: Pt = [6, 0];
  const o6: Pt = [10, -1];
  const a = polar(o2, 2, theta2);
  const b = dyad(a, 5, o4, 5, 1);
  const c = polar(o4, 2.5, Math.atan2(b[1] - o4[1], b[0] - o4[0]) - 1.2);
  const d = dyadBy(c, 5, o6, 4, 1, 1);
  return {
    links: ['ground', 'crank', 'coupler', 'rocker', 'coupler2', 'output'],
    joints: [
      R('O2', 'ground', 'crank', o2),
      R('A', 'crank', 'coupler', a),
      R('B', 'coupler', 'rocker', b),
      R('O4', 'rocker', 'ground', o4),
      R('C', 'rocker', 'coupler2', c),
      R('D', 'coupler2', 'output', d),
      R('O6', 'output', 'ground', o6),
    ],
    input: { joint: 'O2' },
  };
}

/** Stephenson I: the ground is the binary link between two ternaries pivoted on it (crank O2AC, rocker O4BE). */
export function stephensonISpec(theta2 = 0.5): MechanismSpec {
  const o2: Pt = [0, 0];
  const o4: Pt = [6, 0];
  const a = polar(o2, 2, theta2);
  const b = dyad(a, 5, o4, 5, 1);
  const c = polar(o2, 1.5, theta2 + 2.2);
  const e = polar(o4, 3, Math.atan2(b[1] - o4[1], b[0] - o4[0]) + 0.9);
  const d = dyadBy(c, 5, e, 4, 1, 1);
  return {
    links: ['ground', 'crank', 'coupler', 'rocker', 'link5', 'link6'],
    joints: [
      R('O2', 'ground', 'crank', o2),
      R('A', 'crank', 'coupler', a),
      R('B', 'coupler', 'rocker', b),
      R('O4', 'rocker', 'ground', o4),
      R('C', 'crank', 'link5', c),
      R('D', 'link5', 'link6', d),
      R('E', 'link6', 'rocker', e),
    ],
    points: [T('P', 'link5', [(c[0] + d[0]) / 2, (c[1] + d[1]) / 2])],
    input: { joint: 'O2' },
  };
}

/**
 * Stephenson II: the ground is a binary link of the two-link chain; driven at the ternary crank O2–A–C, the rest
 * (two binaries to a floating ternary, one more to ground) is a triad, not a chain of dyads.
 */
export function stephensonIISpec(): MechanismSpec {
  const o2: Pt = [0, 0];
  const o6: Pt = [7, 0];
  const a: Pt = [1.2, 1.6];
  const c: Pt = [1.4, -0.6];
  const b: Pt = [4.5, 3.2];
  const e: Pt = [5.2, 0.8];
  const d: Pt = [6.4, 2.6];
  return {
    links: ['ground', 'crank', 'link3', 'link4', 'ternary', 'output'],
    joints: [
      R('O2', 'ground', 'crank', o2),
      R('A', 'crank', 'link3', a),
      R('C', 'crank', 'link4', c),
      R('B', 'link3', 'ternary', b),
      R('E', 'link4', 'ternary', e),
      R('D', 'ternary', 'output', d),
      R('O6', 'output', 'ground', o6),
    ],
    points: [T('P', 'ternary', [(b[0] + e[0] + d[0]) / 3, (b[1] + e[1] + d[1]) / 3])],
    input: { joint: 'O2' },
  };
}

/** Stephenson III: a four-bar whose coupler point drives a dyad to a third ground pivot O6 (a dwell mechanism). */
export function stephensonIIISpec(theta2 = 0.5): MechanismSpec {
  const o2: Pt = [0, 0];
  const o4: Pt = [6, 0];
  const o6: Pt = [3, -5];
  const a = polar(o2, 2, theta2);
  const b = dyad(a, 5, o4, 5, 1);
  const c = polar(a, 3, Math.atan2(b[1] - a[1], b[0] - a[0]) - 0.8);
  const d = dyadBy(c, 5, o6, 4, 0, -1);
  return {
    links: ['ground', 'crank', 'coupler', 'rocker', 'link5', 'output'],
    joints: [
      R('O2', 'ground', 'crank', o2),
      R('A', 'crank', 'coupler', a),
      R('B', 'coupler', 'rocker', b),
      R('O4', 'rocker', 'ground', o4),
      R('C', 'coupler', 'link5', c),
      R('D', 'link5', 'output', d),
      R('O6', 'output', 'ground', o6),
    ],
    input: { joint: 'O2' },
  };
}

/** Jansen's leg with the "holy numbers" (a..m), crank at the origin, drawn at crank angle theta2. */
export function jansenSpec(theta2 = 0.5): MechanismSpec {
  const [a, b, c, d, e, f, g, h, i, j, k, l, m] = [38, 41.5, 39.3, 40.1, 55.8, 39.4, 36.7, 65.7, 49, 50, 61.9, 7.8, 15];
  const o: Pt = [0, 0];
  const q: Pt = [-a, -l];
  const crank = polar(o, m, theta2);
  const upper = dyadBy(crank, j, q, b, 1, 1);
  const back = dyadBy(q, d, upper, e, 0, -1);
  const lower = dyadBy(crank, k, q, c, 1, -1);
  const knee = dyadBy(back, f, lower, g, 0, -1);
  const foot = dyadBy(knee, h, lower, i, 1, -1);
  return {
    links: ['ground', 'crank', 'j', 'k', 'upperTriangle', 'c', 'f', 'foot'],
    joints: [
      R('O', 'ground', 'crank', o),
      R('Cj', 'crank', 'j', crank),
      R('Ck', 'crank', 'k', crank),
      R('Q', 'ground', 'upperTriangle', q),
      R('D', 'j', 'upperTriangle', upper),
      R('Qc', 'ground', 'c', q),
      R('F', 'k', 'c', lower),
      R('E', 'upperTriangle', 'f', back),
      R('G', 'f', 'foot', knee),
      R('Ff', 'foot', 'c', lower),
    ],
    points: [T('Foot', 'foot', foot)],
    input: { joint: 'O' },
  };
}

/** Klann's leg: crank O–A, coupler ternary A–B–C on a lower rocker, leg ternary C–D–Foot on an upper rocker. */
export function klannSpec(theta2 = 0.5): MechanismSpec {
  const o: Pt = [0, 0];
  const oLow: Pt = [-1.6, -0.9];
  const oUp: Pt = [-2.2, -0.6];
  const a = polar(o, 0.8, theta2);
  const b = dyadBy(a, 1.9, oLow, 1.0, 1, -1);
  const c = polar(a, 3.2, Math.atan2(b[1] - a[1], b[0] - a[0]) + 0.25);
  const dd = dyadBy(c, 1.9, oUp, 1.2, 1, 1);
  const foot = polar(c, 3.0, Math.atan2(c[1] - dd[1], c[0] - dd[0]) + 0.35);
  return {
    links: ['ground', 'crank', 'coupler', 'lowerRocker', 'upperRocker', 'leg'],
    joints: [
      R('O', 'ground', 'crank', o),
      R('A', 'crank', 'coupler', a),
      R('B', 'coupler', 'lowerRocker', b),
      R('Olow', 'lowerRocker', 'ground', oLow),
      R('C', 'coupler', 'leg', c),
      R('D', 'leg', 'upperRocker', dd),
      R('Oup', 'upperRocker', 'ground', oUp),
    ],
    points: [T('Foot', 'leg', foot)],
    input: { joint: 'O' },
  };
}

/**
 * Peaucellier–Lipkin: crank c about O2 = (c, 0) carries C through the fixed pivot O = (0, 0); arms |OA| = |OB| = L,
 * rhombus C–A–P–B of side s. P stays on the line x = (L² - s²) / (2c). L - s < 2c < sqrt(L² - s²) keeps the
 * rhombus from flattening.
 */
export function peaucellierSpec(c = 1, L = 3, s = 1.5, theta2 = 0): MechanismSpec {
  const o: Pt = [0, 0];
  const o2: Pt = [c, 0];
  const cc = polar(o2, c, theta2);
  const a = dyad(o, L, cc, s, 1);
  const b = dyad(o, L, cc, s, -1);
  const p = dyadBy(a, s, b, s, 0, 1);
  return {
    links: ['ground', 'crank', 'armA', 'armB', 'sideCA', 'sideCB', 'sideAP', 'sideBP'],
    joints: [
      R('O2', 'ground', 'crank', o2),
      R('O', 'ground', 'armA', o),
      R('Ob', 'ground', 'armB', o),
      R('C', 'crank', 'sideCA', cc),
      R('Cb', 'crank', 'sideCB', cc),
      R('A', 'armA', 'sideCA', a),
      R('Ap', 'armA', 'sideAP', a),
      R('B', 'armB', 'sideCB', b),
      R('Bp', 'armB', 'sideBP', b),
      R('P', 'sideAP', 'sideBP', p),
    ],
    points: [T('Tracer', 'sideAP', p)],
    input: { joint: 'O2' },
  };
}

/** Chebyshev's straight-line linkage: ground 2, crossed rockers 2.5, coupler 1; its midpoint runs nearly straight. */
export function chebyshevSpec(): MechanismSpec {
  const o2: Pt = [0, 0];
  const o4: Pt = [2, 0];
  const a: Pt = [1.5, 2];
  const b: Pt = [0.5, 2];
  return {
    links: ['ground', 'rocker2', 'coupler', 'rocker4'],
    joints: [
      R('O2', 'ground', 'rocker2', o2),
      R('A', 'rocker2', 'coupler', a),
      R('B', 'coupler', 'rocker4', b),
      R('O4', 'rocker4', 'ground', o4),
    ],
    points: [T('M', 'coupler', [1, 2])],
    input: { joint: 'O2' },
  };
}

/** Hoekens' straight-line linkage: ground 2, crank 1, coupler and rocker 2.5, tracer on the coupler 5 from A. */
export function hoekensSpec(theta2 = 0): MechanismSpec {
  const o2: Pt = [0, 0];
  const o4: Pt = [2, 0];
  const a = polar(o2, 1, theta2);
  const b = dyad(a, 2.5, o4, 2.5, 1);
  return {
    links: ['ground', 'crank', 'coupler', 'rocker'],
    joints: [
      R('O2', 'ground', 'crank', o2),
      R('A', 'crank', 'coupler', a),
      R('B', 'coupler', 'rocker', b),
      R('O4', 'rocker', 'ground', o4),
    ],
    points: [T('P', 'coupler', [2 * b[0] - a[0], 2 * b[1] - a[1]])],
    input: { joint: 'O2' },
  };
}

/** The templates, by key. */
export const MECHANISM_TEMPLATES: Record<string, MechanismTemplate> = {
  fourBar: {
    name: 'Four-bar (the report: 6-2-5-5 crank-rocker)',
    spec: fourBarSpec(6, 2, 5, 5),
    inputRange: FULL_TURN,
    note: 'the report’s case study, drawn at θ2 = 0 on the open branch',
  },
  sliderCrank: {
    name: 'Offset slider-crank',
    spec: sliderCrankSpec(2, 5, 1),
    inputRange: FULL_TURN,
    note: 'crank 2, connecting rod 5, offset 1',
  },
  invertedSliderCrank: {
    name: 'Inverted slider-crank (crank-shaper quick return)',
    spec: invertedSliderCrankSpec(2, 4, 8),
    inputRange: FULL_TURN,
    note: 'crank 2 turning about O2, 4 above the slotted rocker’s pivot O4',
  },
  whitworth: {
    name: 'Whitworth quick return',
    spec: whitworthSpec(),
    inputRange: FULL_TURN,
    note: 'crank 2, slotted link about O4 1 below O2, rod 5 to the ram',
  },
  scotchYoke: {
    name: 'Scotch yoke',
    spec: scotchYokeSpec(),
    inputRange: FULL_TURN,
    note: 'crank 2; the yoke moves as 2 cos θ',
  },
  pistonDriven: {
    name: 'Piston-driven slider-crank (input on the P joint)',
    spec: pistonDrivenSpec(),
    inputRange: [-2.3, 1.6],
    note: 'the piston pushes the crank; the crank stops at the dead centres',
  },
  wattI: {
    name: 'Watt I six-bar',
    spec: wattISpec(),
    inputRange: FULL_TURN,
    note: 'the four-bar 6-2-5-5 with a dyad between coupler and rocker',
  },
  wattII: { name: 'Watt II six-bar', spec: wattIISpec(), inputRange: FULL_TURN, note: 'two four-bars in series' },
  stephensonI: {
    name: 'Stephenson I six-bar',
    spec: stephensonISpec(),
    inputRange: FULL_TURN,
    note: 'a dyad between the ternary crank and the ternary rocker',
  },
  stephensonII: {
    name: 'Stephenson II six-bar',
    spec: stephensonIISpec(),
    inputRange: [-2.2, 0.8],
    note: 'a triad: solved by Newton on all links',
  },
  stephensonIII: {
    name: 'Stephenson III six-bar',
    spec: stephensonIIISpec(),
    inputRange: FULL_TURN,
    note: 'a coupler-driven dyad to a third pivot',
  },
  jansen: {
    name: 'Jansen’s leg',
    spec: jansenSpec(),
    inputRange: FULL_TURN,
    note: 'the holy numbers; the foot traces the walking curve',
  },
  klann: {
    name: 'Klann’s leg',
    spec: klannSpec(),
    inputRange: FULL_TURN,
    note: 'illustrative proportions of the Klann topology',
  },
  peaucellier: {
    name: 'Peaucellier–Lipkin',
    spec: peaucellierSpec(),
    inputRange: [-1.4, 1.4],
    note: 'the tracer runs on x = 3.375 exactly',
  },
  chebyshev: {
    name: 'Chebyshev’s straight line',
    spec: chebyshevSpec(),
    inputRange: [-0.25, 0.8],
    note: 'a double rocker; the coupler’s midpoint runs nearly straight',
  },
  hoekens: {
    name: 'Hoekens’ straight line',
    spec: hoekensSpec(),
    inputRange: FULL_TURN,
    note: 'crank 1, ground 2, coupler and rocker 2.5; tracer 5 along the coupler',
  },
};
