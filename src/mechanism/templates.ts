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
};
