import { degToRad, radToDeg } from '../../../solver/angles';
import { fitView } from '../../../shared/canvas/view';
import { formatDeg, formatNumber } from '../../../shared/format';
import type { Messages } from '../../../shared/i18n/messages';
import type { PrintFact } from '../../../shared/print/PrintFacts';
import type { SynFunctionState } from '../../../shared/state/slices/synFunctionSlice';
import type { LengthUnit } from '../../../shared/state/slices/designSlice';
import type { SynthesisPrintContent } from '../print/synthesisPrint';
import { printFigure } from '../print/synthesisPrint';
import type { SynthesisMessages } from '../synthesisMessages';
import { checkText } from './FunctionFacts';
import type { FunctionMessages } from './functionMessages';
import { drawFunction, functionBounds } from './functionPicture';
import type { FunctionDesign } from './functionSolve';

const FITTED = { zoom: 1, panX: 0, panY: 0 };

/** What the Function mode prints from: its state, the design (null: none, with the problem in words) and the strings. */
export interface FunctionPrintSources {
  s: SynFunctionState;
  fd: FunctionDesign | null;
  problem: string | null;
  unit: LengthUnit;
  st: SynthesisMessages;
  fm: FunctionMessages;
  t: Messages;
}

/**
 * The Function mode's print content: the function and its ranges, the precision points' count and the length unit;
 * the generator's lengths with the unit, type, branch and largest structural error as the card says them, its
 * defects and the page's checks, the precision points with the error at each, and the linkage at the range's start.
 */
export function functionPrintContent({ s, fd, problem, unit, st, fm, t }: FunctionPrintSources): SynthesisPrintContent {
  const m = st.print;
  const n = (x: number) => formatNumber(x, 6);
  const deg = (r: readonly [number, number]) => `${formatDeg(r[0], 2)}° … ${formatDeg(r[1], 2)}°`;
  const task: PrintFact[] = [
    { key: 'length-unit', label: m.lengthUnit, value: unit },
    { key: 'function', label: fm.expressionLabel, value: s.expression, wide: true },
    { key: 'x-range', label: 'x', value: `${n(s.xRange[0])} … ${n(s.xRange[1])}` },
    { key: 'theta2-range', label: 'θ2', value: deg(s.theta2RangeDeg) },
    { key: 'theta4-range', label: 'θ4', value: deg(s.theta4RangeDeg) },
    { key: 'precision-points', label: fm.precisionPoints, value: String(s.precisionPoints) },
  ];
  if (!fd)
    return {
      title: m.title(st.modeFunction),
      task,
      design: [],
      defects: [],
      table: null,
      figureSvg: null,
      note: problem ?? m.noResult,
    };
  const { links, branch, maxError, defects } = fd.result;
  const f5 = (v: number) => formatNumber(v, 5);
  const percent = (100 * maxError) / Math.abs(fd.y1 - fd.y0);
  const design: PrintFact[] = [
    {
      key: 'links',
      label: m.links,
      value: `${fm.links(f5(links.r1), f5(links.r2), f5(links.r3), f5(links.r4))} ${unit}`,
      wide: true,
    },
    { key: 'type', label: m.linkType, value: fm.typeLine(t.types[fd.type]) },
    { key: 'branch', label: '', value: fm.branchLine(branch === 'open' ? t.branchOpen : t.branchCrossed) },
    {
      key: 'max-error',
      label: st.structuralError,
      value: Number.isFinite(maxError)
        ? fm.maxError(formatNumber(maxError, 3), formatNumber(percent, 3))
        : fm.maxErrorNone,
      wide: true,
    },
    {
      key: 'placement',
      label: m.placement,
      value: m.placementValue(f5(fd.design.O2.x), f5(fd.design.O2.y), formatDeg(radToDeg(fd.design.groundAngle), 2)),
      wide: true,
    },
  ];
  const words = [...fd.checks.map((c) => checkText(c, fm)), ...defects.map((d) => fm.defectWords[d])];
  const picture = {
    fd,
    theta2Range: [degToRad(s.theta2RangeDeg[0]), degToRad(s.theta2RangeDeg[1])] as [number, number],
    theta4Range: [degToRad(s.theta4RangeDeg[0]), degToRad(s.theta4RangeDeg[1])] as [number, number],
    theta2: degToRad(s.theta2RangeDeg[0]),
  };
  return {
    title: m.title(st.modeFunction),
    task,
    design,
    defects: words.length > 0 ? words : [fm.noDefects],
    table: {
      caption: st.precisionPoints,
      columns: ['', 'x', 'θ2 (°)', 'θ4 (°)', st.structuralError],
      rows: fd.precision.map((p, i) => ({
        key: `X${i + 1}`,
        cells: [
          String(i + 1),
          n(p.x),
          formatDeg(radToDeg(p.theta2), 3),
          formatDeg(radToDeg(p.theta4), 3),
          formatNumber(p.error, 3, Math.abs(fd.y1 - fd.y0)),
        ],
      })),
    },
    figureSvg: printFigure(
      (w, h) => (ctx) => drawFunction(ctx, picture, fitView(functionBounds(picture), w, h, FITTED)),
    ),
    note: null,
  };
}
