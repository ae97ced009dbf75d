import { radToDeg } from '../../../solver/angles';
import type { Point } from '../../../solver/kinematics';
import type { PlacedFourBar } from '../../../synthesis/types';
import { placedCouplerPoint, placedJoints } from '../../../synthesis/placed';
import { fitView } from '../../../shared/canvas/view';
import { formatDeg, formatNumber } from '../../../shared/format';
import type { Messages } from '../../../shared/i18n/messages';
import type { PrintFact } from '../../../shared/print/PrintFacts';
import type { SynPathState } from '../../../shared/state/appState';
import type { LengthUnit } from '../../../shared/state/slices/designSlice';
import type { PrintTable, SynthesisPrintContent } from '../print/synthesisPrint';
import { printFigure } from '../print/synthesisPrint';
import type { SynthesisMessages } from '../synthesisMessages';
import { defectsText, distanceText, errorSumText, typeText } from './CandidateList';
import type { DesignChoice } from './ChosenDesign';
import type { PathCurve } from './drawPathScene';
import { drawPathScene, pathSceneBounds } from './drawPathScene';
import { pathBoundsOf, targetsExtent } from './pathTaskOf';

const FITTED = { zoom: 1, panX: 0, panY: 0 };

/** A design shown in print: the linkage, the θ2 (radians) it is drawn at, and its facts. */
export type PrintedChoice = DesignChoice & { theta2: number };

/**
 * The facts of a placed design as the chosen card shows them (lengths to 4 digits, its type and defects) with the
 * length unit, the coupler point (|AP| and its angle from AB) and the placement (O2, the ground line's angle).
 */
export function placedDesignFacts(
  c: PrintedChoice,
  name: string,
  unit: LengthUnit,
  st: SynthesisMessages,
  t: Messages,
): PrintFact[] {
  const m = st.print;
  const f4 = (x: number) => formatNumber(x, 4);
  const l = c.design.links;
  const d = c.design;
  return [
    { key: 'candidate', label: m.candidate, value: name },
    {
      key: 'links',
      label: m.links,
      value: `${st.lengths(f4(l.r1), f4(l.r2), f4(l.r3), f4(l.r4))} ${unit}`,
      wide: true,
    },
    { key: 'type', label: m.linkType, value: typeText(c.facts, t, st) },
    { key: 'mu-min', label: st.minTransmission, value: `${formatDeg(c.facts.muMinDeg, 1)}°` },
    {
      key: 'coupler',
      label: m.coupler,
      value: m.couplerValue(f4(d.pDist), unit, formatDeg(radToDeg(d.pAngle), 2)),
      wide: true,
    },
    {
      key: 'placement',
      label: m.placement,
      value: m.placementValue(f4(d.O2.x), f4(d.O2.y), formatDeg(radToDeg(d.groundAngle), 2)),
      wide: true,
    },
  ];
}

/** The targets with where a design passes them: θ2 (degrees) and the distance d from the coupler point, per target. */
export function targetErrorTable(
  targets: readonly Point[],
  passes: readonly { design: PlacedFourBar; theta2: number }[] | null,
  given: readonly number[] | null,
  st: SynthesisMessages,
): PrintTable {
  const m = st.print;
  const size = targetsExtent(targets).size;
  const f = (x: number) => formatNumber(x, 6);
  const columns = [m.columnTarget, st.tableX, st.tableY];
  if (given) columns.push(m.columnGiven);
  if (passes) columns.push(m.columnDesignTheta2, m.columnDistance);
  const rows = targets.map((p, i) => {
    const cells = [st.targetName(i + 1), f(p.x), f(p.y)];
    if (given) cells.push(Number.isFinite(given[i]) ? formatDeg(given[i], 2) : '—');
    const at = passes?.[i];
    if (at) {
      const q = placedCouplerPoint(at.design, at.theta2);
      const deg = ((radToDeg(at.theta2) % 360) + 360) % 360;
      cells.push(formatDeg(deg, 2), q ? distanceText(Math.hypot(q.x - p.x, q.y - p.y), size) : '—');
    }
    return { key: `T${i + 1}`, cells };
  });
  return { caption: st.targetsTitle, columns, rows };
}

/** The targets, the chosen coupler curve and the linkage at theta2, as the canvas draws them, fitted to the figure. */
export function pathFigureSvg(
  targets: readonly Point[],
  curve: PathCurve | null,
  choice: PrintedChoice | null,
  st: SynthesisMessages,
): string {
  const curves = curve ? [{ ...curve, faint: false }] : [];
  const pose = choice ? placedJoints(choice.design, choice.theta2) : null;
  const names = targets.map((_, i) => st.targetName(i + 1));
  const bounds = pathSceneBounds({ targets, curves, pose: null, design: choice?.design ?? null });
  return printFigure(
    (w, h) => (ctx) =>
      drawPathScene(ctx, { targets, selected: null, names, curves, pose }, fitView(bounds, w, h, FITTED)),
  );
}

/** The Path mode's task as printed: the length unit, targets, timing, bounds, pivot box, input and seed. */
export function pathTaskFacts(s: SynPathState, unit: LengthUnit, st: SynthesisMessages): PrintFact[] {
  const m = st.print;
  const b = pathBoundsOf(s);
  const f = (x: number) => formatNumber(x, 6);
  const timing =
    s.timing === 'step'
      ? m.timingStepValue(formatDeg(s.timingStepDeg, 2))
      : s.timing === 'given'
        ? st.timingGiven
        : st.timingFree;
  return [
    { key: 'length-unit', label: m.lengthUnit, value: unit },
    { key: 'targets', label: st.targetsTitle, value: String(s.targets.length) },
    { key: 'timing', label: st.timingLegend, value: timing },
    { key: 'bounds', label: m.bounds, value: m.boundsValue(f(b.length), f(b.coupler)) },
    {
      key: 'pivot-box',
      label: st.pivotBox,
      value: m.pivotBoxValue(f(b.pivot.min.x), f(b.pivot.max.x), f(b.pivot.min.y), f(b.pivot.max.y)),
    },
    { key: 'input', label: st.inputLegend, value: s.input === 'crank' ? st.inputCrank : st.inputAny },
    { key: 'seed', label: m.seed, value: String(s.seed) },
  ];
}

/** Σd² and the largest distance of a candidate, as the candidate list shows them. */
export function pathErrorFacts(error: number, maxDistance: number, size: number, st: SynthesisMessages): PrintFact[] {
  return [
    { key: 'error-sum', label: st.errorSum, value: errorSumText(error, size) },
    { key: 'max-distance', label: st.maxDistance, value: distanceText(maxDistance, size) },
  ];
}

/** The defects of a design in words, as the chosen card lists them. */
export function defectLines(c: PrintedChoice, st: SynthesisMessages): string[] {
  return defectsText(c.facts, st).split('; ');
}

/** What the Path mode prints from: its state, the length unit, the candidate chosen and the linkage shown. */
export interface PathPrintSources {
  s: SynPathState;
  unit: LengthUnit;
  /** The candidate chosen (its θ2 at each target, Σd², max d) and its rank (0-based); null before a run. */
  solution: { design: PlacedFourBar; theta2: number[]; error: number; maxDistance: number } | null;
  rank: number;
  /** The linkage shown: the candidate (0) or one of its cognates. */
  choices: readonly PrintedChoice[];
  shown: number;
  stale: boolean;
  st: SynthesisMessages;
  t: Messages;
}

/**
 * The Path mode's print content: the task (targets, timing, bounds, input, seed, unit), the chosen candidate or
 * cognate shown (lengths, type, coupler point, placement, Σd², max d, defects), the distance from each target,
 * and the canvas's picture. An out-of-date result is printed with the note, without distances.
 */
export function pathPrintContent(p: PathPrintSources): SynthesisPrintContent {
  const { s, st } = p;
  const choice = p.choices[p.shown] ?? null;
  const sol = p.solution;
  const size = targetsExtent(s.targets).size;
  const name =
    p.shown === 0 ? st.candidateName(p.rank + 1) : `${st.candidateName(p.rank + 1)} · ${st.cognateName(p.shown)}`;
  const design =
    choice && sol
      ? [...placedDesignFacts(choice, name, p.unit, st, p.t), ...pathErrorFacts(sol.error, sol.maxDistance, size, st)]
      : [];
  const passes = sol && !p.stale ? s.targets.map((_, i) => ({ design: sol.design, theta2: sol.theta2[i] })) : null;
  const curve = choice ? { x: choice.facts.curve.x, y: choice.facts.curve.y, faint: false } : null;
  return {
    title: st.print.title(st.modePath),
    task: pathTaskFacts(s, p.unit, st),
    design,
    defects: choice && sol ? defectLines(choice, st) : [],
    table:
      s.targets.length > 0
        ? targetErrorTable(s.targets, passes, s.timing === 'given' ? s.givenTheta2Deg : null, st)
        : null,
    figureSvg:
      s.targets.length > 0 ? pathFigureSvg(s.targets, p.stale ? null : curve, p.stale ? null : choice, st) : null,
    note: !sol ? st.print.noResult : p.stale ? st.staleResults : null,
  };
}

/** What the Nine points mode prints from: the points, the class chosen (0-based), its cognates and the one shown. */
export interface NinePrintSources {
  targets: readonly Point[];
  unit: LengthUnit;
  rank: number;
  /** Each cognate as drawn, and its θ2 (radians) and assembly at each of the nine points. */
  choices: readonly PrintedChoice[];
  passes: readonly { design: PlacedFourBar; theta2: number }[][];
  shown: number;
  stale: boolean;
  /** The coupler curve drawn strong (the whole turn on the assembly it moves on). */
  curve: PathCurve | null;
  st: SynthesisMessages;
  t: Messages;
  /** The mode's name and the class's name ("Linkage 3"). */
  mode: string;
  className: string;
}

/** The Nine points mode's print content: the nine points, the class's cognate shown, its distance at each point. */
export function ninePrintContent(p: NinePrintSources): SynthesisPrintContent {
  const { st } = p;
  const choice = p.choices[p.shown] ?? null;
  const name = p.shown === 0 ? p.className : `${p.className} · ${st.cognateName(p.shown)}`;
  return {
    title: st.print.title(p.mode),
    task: [
      { key: 'length-unit', label: st.print.lengthUnit, value: p.unit },
      { key: 'targets', label: st.targetsTitle, value: String(p.targets.length) },
    ],
    design: choice ? placedDesignFacts(choice, name, p.unit, st, p.t) : [],
    defects: choice ? defectLines(choice, st) : [],
    table:
      p.targets.length > 0
        ? targetErrorTable(p.targets, choice && !p.stale ? (p.passes[p.shown] ?? null) : null, null, st)
        : null,
    figureSvg:
      p.targets.length > 0 ? pathFigureSvg(p.targets, p.stale ? null : p.curve, p.stale ? null : choice, st) : null,
    note: !choice ? st.print.noResult : p.stale ? st.staleResults : null,
  };
}
