import { radToDeg, wrapAngle } from '../../../solver/angles';
import { placedJoints } from '../../../synthesis/placed';
import { fitView } from '../../../shared/canvas/view';
import { formatDeg, formatNumber } from '../../../shared/format';
import type { Messages } from '../../../shared/i18n/messages';
import type { PrintFact } from '../../../shared/print/PrintFacts';
import type { SynMotionState } from '../../../shared/state/slices/synMotionSlice';
import type { LengthUnit } from '../../../shared/state/slices/designSlice';
import type { PrintTable, SynthesisPrintContent } from '../print/synthesisPrint';
import { printFigure } from '../print/synthesisPrint';
import type { SynthesisMessages } from '../synthesisMessages';
import type { MotionMessages } from './motionMessages';
import type { MotionPicture } from './motionPicture';
import { drawMotion, motionBounds } from './motionPicture';
import type { MotionCandidate, MotionOutcome } from './motionSolve';
import { toPose } from './motionSolve';
import { problemText } from './motionText';

const FITTED = { zoom: 1, panX: 0, panY: 0 };

/** Position (length unit) and angle (radians) error of a design at each pose, for the exact methods (2 to 5 poses). */
export function exactPoseErrors(s: SynMotionState, c: MotionCandidate): { position: number; angle: number }[] {
  const poses = s.poses.map(toPose);
  // The coupler turns with A→B: its turn from pose 1 against the poses' own turn from pose 1.
  const ab = (theta2: number) => {
    const j = placedJoints(c.design, theta2);
    return j ? { P: j.P, angle: Math.atan2(j.B.y - j.A.y, j.B.x - j.A.x) } : null;
  };
  const first = ab(c.theta2[0]);
  return poses.map((pose, i) => {
    const at = ab(c.theta2[i]);
    if (!at || !first) return { position: Infinity, angle: NaN };
    return {
      position: Math.hypot(at.P.x - pose.x, at.P.y - pose.y),
      angle: wrapAngle(at.angle - first.angle - (pose.angle - poses[0].angle)),
    };
  });
}

/** What the Motion mode prints from. */
export interface MotionPrintSources {
  s: SynMotionState;
  outcome: MotionOutcome;
  picture: MotionPicture;
  unit: LengthUnit;
  st: SynthesisMessages;
  mt: MotionMessages;
  t: Messages;
}

/**
 * The Motion mode's print content: the poses and the method's options, the design found (lengths with the unit,
 * fixed pivots, type, coupler point and placement, rms for six or more poses), its defects, its error at each pose
 * (the method's own for six or more, else measured here) and the canvas's picture.
 */
export function motionPrintContent({
  s,
  outcome,
  picture,
  unit,
  st,
  mt,
  t,
}: MotionPrintSources): SynthesisPrintContent {
  const m = st.print;
  const f = (v: number) => formatNumber(v, 5);
  const n = s.poses.length;
  const task: PrintFact[] = [
    { key: 'length-unit', label: m.lengthUnit, value: unit },
    { key: 'poses', label: mt.posesTitle, value: String(n) },
    { key: 'method', label: st.print.task, value: mt.methodFor[outcome.count] },
  ];
  if (n === 2)
    task.push(
      { key: 'ground-length', label: mt.groundLength, value: s.groundLength === null ? '—' : f(s.groundLength) },
      { key: 'time-ratio', label: mt.timeRatio, value: formatNumber(s.timeRatio, 4) },
    );
  if (n === 3)
    task.push({
      key: 'pivots-placed',
      label: s.pivotChoice === 'moving' ? mt.pivotMoving : mt.pivotFixed,
      value: s.pivots.map((p) => `(${f(p.x)}, ${f(p.y)})`).join(', '),
    });
  const c = outcome.chosen;
  const design: PrintFact[] = [];
  let table: PrintTable;
  const poseRows = s.poses.map((p, i) => ({
    key: `P${i + 1}`,
    cells: [String(i + 1), formatNumber(p.x, 6), formatNumber(p.y, 6), formatDeg(p.angleDeg, 2)],
  }));
  const columns = [mt.columnPose, mt.columnX, mt.columnY, mt.columnAngle];
  if (c) {
    const { links, O2, groundAngle, pDist, pAngle } = c.design;
    const O4 = { x: O2.x + links.r1 * Math.cos(groundAngle), y: O2.y + links.r1 * Math.sin(groundAngle) };
    design.push(
      {
        key: 'links',
        label: m.links,
        value: `${mt.links(f(links.r1), f(links.r2), f(links.r3), f(links.r4))} ${unit}`,
        wide: true,
      },
      { key: 'pivots', label: mt.pivotFixed, value: mt.pivotsLine(f(O2.x), f(O2.y), f(O4.x), f(O4.y)), wide: true },
      { key: 'type', label: m.linkType, value: t.types[c.type] },
      {
        key: 'ground-angle',
        label: m.placement,
        value: m.placementValue(f(O2.x), f(O2.y), formatDeg(radToDeg(groundAngle), 2)),
      },
      {
        key: 'coupler',
        label: m.coupler,
        value: m.couplerValue(f(pDist), unit, formatDeg(radToDeg(pAngle), 2)),
        wide: true,
      },
    );
    if (c.rms !== undefined) design.push({ key: 'rms', label: 'rms', value: formatNumber(c.rms, 3) });
    const errors = c.errors ?? exactPoseErrors(s, c);
    table = {
      caption: mt.errorsTitle,
      columns: [...columns, mt.columnPositionError, mt.columnAngleError],
      rows: poseRows.map((r, i) => ({
        ...r,
        cells: [...r.cells, formatNumber(errors[i].position, 3, 1), formatDeg(radToDeg(errors[i].angle), 2)],
      })),
    };
  } else table = { caption: mt.posesTitle, columns, rows: poseRows };
  return {
    title: m.title(st.modeMotion),
    task,
    design,
    defects: c ? (c.defects.length ? c.defects.map((d) => mt.defectWords[d]) : [mt.noDefects]) : [],
    table,
    figureSvg: printFigure((w, h) => (ctx) => drawMotion(ctx, picture, fitView(motionBounds(picture), w, h, FITTED))),
    note: c ? null : outcome.problem ? problemText(mt, outcome.problem) : m.noResult,
  };
}
