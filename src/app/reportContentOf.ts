import { radToDeg, radToDeg180, radToDeg360 } from '../solver/angles';
import type { ExportSubject } from '../shared/fileNames';
import { exportChart } from '../shared/charts/exportChart';
import { formatDeg, formatNumber } from '../shared/format';
import { designFacts } from '../shared/linkage/designFacts';
import type { ShownFrame } from '../shared/linkage/shownFrame';
import { formatInputRange } from '../shared/state/inputRange';
import type { Messages } from '../shared/i18n/messages';
import type { CycleResponse, PointResponse } from '../shared/solution';
import type { CycleDegrees } from '../shared/charts/chartInputs';
import { linkageSvg, plotExport } from '../features/export/exporters';
import { grashofSumsText } from '../features/simulator/grashofText';
import { motionFacts } from '../features/simulator/motionFacts';
import type { DesignInfo } from '../features/simulator/useDesignMetrics';
import type { ReportContent, ReportFact, ReportPlot } from '../features/report/reportContent';
import type { ReportMessages } from '../features/report/reportMessages';
import { omegaToUnit } from '../shared/state/inputMotion';
import { localPose } from '../shared/linkage/localPose';
import { forceSetup } from '../features/forces/forceModel';
import { poseForces } from '../features/forces/forceModel';
import { cycleFacts, poseFacts } from '../features/forces/forceFacts';
import { cycleForces } from '../features/forces/forceCycleData';
import { forceChartExport } from '../features/forces/forceCharts';
import { forcesMessages } from '../features/forces/forcesMessages';
import type { AppState, ForcePlotKind } from '../shared/state/appState';

/** The report figure's drawing size (CSS pixels): the canvas's scene drawn again at this size, as SVG. */
export const REPORT_FIGURE_SIZE = { width: 560, height: 380 } as const;

/** The report plots' drawing size (CSS pixels), about two thirds of the exported plots'. */
export const REPORT_PLOT_SIZE = { width: 440, height: 260 } as const;

/** The report's bearing-load diagram size (CSS pixels): square, as its export, one newton as long on x as on y. */
export const REPORT_FORCE_POLAR_SIZE = { width: 300, height: 300 } as const;

/** What the report is made from: the frame on screen, the cycle, the design metrics, the plotted angles and the strings. */
export interface ReportSources {
  frame: ShownFrame;
  cycle: CycleResponse | null;
  design: DesignInfo | null;
  deg: CycleDegrees | null;
  point: PointResponse | null;
  t: Messages;
  m: ReportMessages;
}

/** The plots the plots card shows for its choice (angles, velocities, accelerations; other choices: the angles). */
function chosenPlots(frame: ShownFrame): Exclude<ExportSubject, 'linkage' | 'convergence'>[] {
  const { plotKind, plotLayout } = frame.state.display;
  if (plotKind === 'velocities') return ['omega'];
  if (plotKind === 'accelerations') return ['alpha'];
  return plotLayout === 'together' ? ['both'] : ['theta3', 'theta4'];
}

/**
 * The input and units: ω2 in its unit and the length unit; for a placed design (a synthesized one: moved off the
 * origin, turned, or with targets) its coupler point, placement and targets, numbers as the URL gives them (6 digits).
 */
function setupFacts(s: AppState, t: Messages, m: ReportMessages): ReportFact[] {
  const n = (x: number) => formatNumber(x);
  const unit = s.motion.omegaUnit;
  const out: ReportFact[] = [
    { key: 'length-unit', label: m.lengthUnit, value: s.design.lengthUnit },
    {
      key: 'omega2',
      label: m.omega2,
      value: `${n(omegaToUnit(s.motion.omega2RadPerS, unit))} ${t.omegaUnits[unit]}`,
    },
  ];
  const pl = s.design.placement;
  const targets = s.synPath.targets;
  const placed = pl.x !== 0 || pl.y !== 0 || pl.angleDeg !== 0 || targets.length > 0;
  if (!placed) return out;
  const c = s.design.coupler;
  out.push(
    { key: 'coupler', label: m.couplerPoint, value: `${n(c.distance)} ${s.design.lengthUnit}, ${n(c.angleDeg)}°` },
    { key: 'placement', label: m.placementLabel, value: m.placement(n(pl.x), n(pl.y), n(pl.angleDeg)), wide: true },
  );
  if (targets.length > 0)
    out.push({
      key: 'targets',
      label: `${m.targets} (${targets.length})`,
      value: targets.map((p, i) => `T${i + 1} (${n(p.x)}, ${n(p.y)})`).join('; '),
      wide: true,
    });
  return out;
}

/** The force plot the report prints with Forces on: the one chosen in the plots card, else the input torque. */
function chosenForcePlot(s: AppState): ForcePlotKind {
  const k = s.display.plotKind;
  return k === 'pinForces' || k === 'bearing' ? k : 'torque';
}

/**
 * With Forces on, the forces panel's lines as it shows them (keys forces-<its test id>): T12, the pin forces and
 * shaking at the state's θ2, and the cycle's mean, RMS and peak torque, ΔE and flywheel inertia; and the chosen
 * force plot over the turn, drawn as the plots card draws it (its axes, units and θ2 marker); else none.
 */
function forceReport(s: AppState): { facts: ReportFact[]; plot: ReportPlot | null } {
  if (!s.forces.enabled) return { facts: [], plot: null };
  const ft = forcesMessages.get(s.shell.locale);
  const setup = forceSetup(s);
  const { linkage, branch, coupler } = s.design;
  const local = localPose(linkage, s.motion.theta2Deg, branch, coupler, false);
  const pose = poseForces(setup, local.theta2Rad, local.pose);
  const at = poseFacts(pose, ft).map((f) => ({
    key: `forces-${f.key}`,
    label: f.label,
    value: f.value,
  }));
  const turn = cycleForces(setup, branch, s.solver.samples);
  const c = cycleFacts(turn, setup.input.omega2, ft);
  const cycle: ReportFact[] = [
    { key: 'forces-mean', label: ft.meanTorque, value: c.mean },
    { key: 'forces-rms', label: ft.rmsTorque, value: c.rms },
    { key: 'forces-peak', label: ft.peakTorque, value: c.peak },
    { key: 'forces-energy', label: ft.energyFluctuation, value: c.energy },
    {
      key: 'forces-flywheel',
      label: ft.flywheelInertia(formatNumber(s.forces.speedFluctuation, 4)),
      value: c.flywheel,
    },
  ];
  const kind = chosenForcePlot(s);
  const size = kind === 'bearing' ? REPORT_FORCE_POLAR_SIZE : REPORT_PLOT_SIZE;
  const chart = { ...forceChartExport(kind, turn, pose, radToDeg360(local.theta2Rad), ft), ...size };
  const title = kind === 'torque' ? ft.chartTorque : kind === 'pinForces' ? ft.chartPinForces : ft.chartBearing;
  return { facts: [...at, ...cycle], plot: { title, svg: exportChart(chart, 'svg'), kind } };
}

/**
 * The printed report's content, formatted as the panels format it (so the numbers match them): the figure of the
 * frame on screen with r1..r4 and its lengths, the Grashof check, type, Barker class and input range (the numbers
 * panel), the design metrics (the design panel), θ3, θ4, ω3, ω4, α3, α4 and μ at the frame's θ2 (numbers and motion
 * panels), and the chosen plots drawn by the chart kit.
 */
export function reportContentOf({ frame, cycle, design, deg, point, t, m }: ReportSources): ReportContent {
  const s = frame.state;
  const l = s.design.linkage;
  const lengths = (['r1', 'r2', 'r3', 'r4'] as const).map((k) => `${k} = ${formatNumber(l[k])}`).join(', ');
  const c = cycle?.classification ?? null;
  const verdict = !c ? '—' : c.type === 'change-point' ? t.grashofChangePoint : c.grashof ? t.grashofYes : t.grashofNo;
  const classification: ReportFact[] = [
    { key: 'grashof-sums', label: t.grashofCheck, value: c ? grashofSumsText(c) : '—', wide: true },
    { key: 'grashof', label: '', value: verdict, wide: true },
    { key: 'linkage-type', label: t.linkageType, value: c ? t.types[c.type] : '—' },
    { key: 'barker', label: t.barker, value: c ? c.barker : '—' },
    { key: 'input-range', label: t.inputRange, value: c ? formatInputRange(c.inputRange, t) : '—' },
  ];
  const facts = design ? designFacts(design.metrics, design.range) : null;
  const metrics: ReportFact[] = [];
  if (facts) {
    metrics.push(
      { key: 'mu-min', label: t.designMuMin, value: `${facts.muMinText} (${t.designAt(facts.muMinAt.theta2Text)})` },
      { key: 'mu-max', label: t.designMuMax, value: `${facts.muMaxText} (${t.designAt(facts.muMaxAt.theta2Text)})` },
    );
    for (const dc of facts.deadCentres ?? []) {
      metrics.push({
        key: `dc-${dc.kind}`,
        label: dc.kind === 'extended' ? t.deadCentreExtended : t.deadCentreFolded,
        value: `${t.designAt(dc.theta2Text)}, ${t.deadCentreTheta4(dc.theta4Text)}`,
      });
    }
    if (facts.swingText) metrics.push({ key: 'swing', label: t.swing, value: facts.swingText });
    if (facts.timeRatioText) metrics.push({ key: 'time-ratio', label: t.timeRatio, value: facts.timeRatioText });
  }
  const pose = frame.marker.pose;
  const deg3 = (rad: number) => `${formatDeg(radToDeg180(rad), 3)}°`;
  const motion = frame.motion ? motionFacts(frame.motion, t) : [];
  const rate = (key: string) => motion.find((f) => f.key === key);
  const atTheta2: ReportFact[] = [
    { key: 'theta3', label: 'θ3', value: pose ? deg3(pose.theta3) : '—' },
    { key: 'theta4', label: 'θ4', value: pose ? deg3(pose.theta4) : '—' },
    ...(['omega3', 'omega4', 'alpha3', 'alpha4'] as const).map((key) => ({
      key,
      label: rate(key)?.label ?? key,
      value: rate(key)?.value ?? '—',
    })),
    { key: 'mu', label: t.transmissionAngle, value: pose ? `${formatDeg(radToDeg(pose.mu), 3)}°` : '—' },
  ];
  const ctx = { frame, point, deg, t, canvasSize: REPORT_FIGURE_SIZE };
  const plots = chosenPlots(frame).map((subject) => {
    // Drawn smaller than the export's own size, so its texts print larger on the page.
    const chart = { ...plotExport(subject, ctx), ...REPORT_PLOT_SIZE };
    return { title: subject, svg: exportChart(chart, 'svg') };
  });
  const forces = forceReport(s);
  return {
    title: m.title,
    subtitle: `${lengths} · ${s.design.branch === 'open' ? t.branchOpen : t.branchCrossed}`,
    figureSvg: linkageSvg(frame.scene, s.display.view, REPORT_FIGURE_SIZE.width, REPORT_FIGURE_SIZE.height),
    figureCaption: m.lengths(lengths),
    classification,
    metrics,
    atTheta2Title: m.atTheta2(formatDeg(radToDeg360(frame.marker.theta2Rad), 2)),
    atTheta2,
    plots,
    setup: setupFacts(s, t, m),
    forces: forces.facts,
    forcePlot: forces.plot,
  };
}
