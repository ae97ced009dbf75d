import { GROUND } from '../../mechanism';
import type { MechanismSpec, MechanismSweep } from '../../mechanism';
import { radToDeg } from '../../solver/angles';
import type { MechMessages } from './mechMessagesEn';

/** What a plot shows against the input: a link's rotation, a slider's slide, a point's speed or acceleration. */
export type MechPlotKind = 'angle' | 'slide' | 'speed' | 'accel';

/** A plot's choice as text: kind:id ('angle:coupler', 'speed:Foot'), or '' for none. */
export type MechPlotChoice = string;

/** Every choice a linkage offers, in the menu's order: links' angles, sliders, then each point's speed and acceleration. */
export function plotChoices(spec: MechanismSpec): MechPlotChoice[] {
  const ids = [...spec.joints.map((j) => j.id), ...(spec.points ?? []).map((p) => p.id)];
  return [
    ...spec.links.filter((l) => l !== GROUND).map((l) => `angle:${l}`),
    ...spec.joints.filter((j) => j.kind === 'P').map((j) => `slide:${j.id}`),
    ...ids.map((id) => `speed:${id}`),
    ...ids.map((id) => `accel:${id}`),
  ];
}

/** The two plots a linkage opens with: the last link's angle (or the first slider's slide), and the last point's speed. */
export function defaultPlots(spec: MechanismSpec): [MechPlotChoice, MechPlotChoice] {
  const slider = spec.joints.find((j) => j.kind === 'P' && j.id !== spec.input.joint);
  const moving = spec.links.filter((l) => l !== GROUND);
  const first = slider ? `slide:${slider.id}` : moving.length > 0 ? `angle:${moving[moving.length - 1]}` : '';
  const last = spec.points?.length ? spec.points[spec.points.length - 1].id : spec.joints[spec.joints.length - 1]?.id;
  return [first, last ? `speed:${last}` : ''];
}

/** A choice split into its kind and id (null when it is not one of the linkage's choices). */
export function parseChoice(spec: MechanismSpec, choice: MechPlotChoice): { kind: MechPlotKind; id: string } | null {
  if (!plotChoices(spec).includes(choice)) return null;
  const i = choice.indexOf(':');
  return { kind: choice.slice(0, i) as MechPlotKind, id: choice.slice(i + 1) };
}

/** The menu's text of a choice. */
export function choiceLabel(choice: { kind: MechPlotKind; id: string }, m: MechMessages): string {
  if (choice.kind === 'angle') return m.plotAngle(choice.id);
  if (choice.kind === 'slide') return m.plotSlide(choice.id);
  if (choice.kind === 'speed') return m.plotSpeed(choice.id);
  return m.plotAccel(choice.id);
}

/** The y axis's label of a kind, for a pin or a slider input. */
export function axisLabel(kind: MechPlotKind, inputKind: 'R' | 'P', m: MechMessages): string {
  if (kind === 'angle') return m.axisAngle;
  if (kind === 'slide') return m.axisSlide;
  if (kind === 'speed') return inputKind === 'R' ? m.axisSpeed : m.axisSpeedP;
  return inputKind === 'R' ? m.axisAccel : m.axisAccelP;
}

/** Whether a kind needs the rates (the worker's sweep) rather than the positions. */
export const needsRates = (kind: MechPlotKind) => kind === 'speed' || kind === 'accel';

/**
 * The y values of a choice on the grid: a link's rotation (degrees, continuous), a slider's slide, a point's speed
 * |v| or acceleration |a| per unit input rate (from a sweep with rates); NaN where not assembled.
 */
export function plotValues(choice: { kind: MechPlotKind; id: string }, sweep: MechanismSweep): Float64Array {
  const { kind, id } = choice;
  if (kind === 'angle') return sweep.links[id].angle.map((a) => radToDeg(a));
  if (kind === 'slide') return Float64Array.from(sweep.sliders[id].s);
  const s = sweep.joints[id] ?? sweep.points[id];
  const [u, w] = kind === 'speed' ? [s.vx, s.vy] : [s.ax, s.ay];
  if (!u || !w) return new Float64Array(s.x.length).fill(NaN);
  return u.map((a, i) => Math.hypot(a, w[i]));
}
