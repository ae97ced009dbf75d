import './MechanismPage.css';
import { useDeferredValue, useEffect, useMemo, useRef, useState } from 'react';
import type { Dispatch } from 'react';
import { GROUND, MECHANISM_TEMPLATES, sweepMechanism } from '../../mechanism';
import type { MechanismSpec } from '../../mechanism';
import { degToRad, radToDeg } from '../../solver/angles';
import type { Action, AppState } from '../../shared/state/appState';
import type { MechForcesSettings, MechPageSettings, MechTemplateKey } from '../../shared/state/slices/mechSlice';
import { METRES_PER_UNIT } from '../../shared/state/slices/designSlice';
import type { LengthUnit } from '../../shared/state/slices/designSlice';
import { mechSpecCodec, templateUrlValue } from '../../shared/state/slices/mechSlice';
import type { JobRunner } from '../../shared/jobs/jobClient';
import type { Bounds, ViewTransform } from '../../shared/canvas/view';
import { emptyBounds, extendBounds, fitView } from '../../shared/canvas/view';
import { exportDrawingPng, exportDrawingSvg } from '../../shared/canvas/exportDrawing';
import { downloadPng, downloadText } from '../../shared/canvas/download';
import type { MarkerAt } from '../../shared/charts/chart';
import { exportChart, specDrawing } from '../../shared/charts/exportChart';
import { xySpec } from '../../shared/charts/xyChart';
import type { XYChartData } from '../../shared/charts/xyChart';
import { formatNumber } from '../../shared/format';
import type { ViewOffset } from '../../shared/state/appState';
import type { MechanismJobs } from './jobs';
import type { MechAnalysis } from './mechAnalysis';
import { analyseMechanism, runRange, valueAt, withRefinedLimits } from './mechAnalysis';
import { csvInputs, mechCsv } from './mechCsv';
import type { MechMessages } from './mechMessages';
import { mechMessagesFor } from './mechMessages';
import { drawMechanism, linkColor } from './drawMechanism';
import { drawnPose, pathOf } from './mechPose';
import type { MechScene, MechSeriesAt } from './mechScene';
import { mechPictureAt } from './mechScene';
import type { MechLiveStage, MechStageFactory } from './stage/mechLiveStage';
import type { Pt } from './mechPose';
import type { MechPlotChoice } from './mechPlots';
import { axisLabel, choiceLabel, defaultPlots, needsRates, parseChoice, plotChoices, plotValues } from './mechPlots';
import { MechPositions } from './MechPositions';
import { AtPlayhead, MechPlotCell, MechStage } from './MechLiveViews';
import type { PlayheadInput } from './MechLiveViews';
import { createPlayheadSource } from './livePlayhead';
import { useJointDrag } from './useJointDrag';
import { TemplateGallery } from './TemplateGallery';
import type { PlaceKind } from './SpecEditor';
import { SpecEditor } from './SpecEditor';
import { addJoint, addLink, addTracer, emptySpec, moveJoint } from './specEdits';
import { useMechDrive } from './useMechDrive';
import { useMechSweepJob } from './useMechSweepJob';
import type { MechForcesJob } from './mechForces';
import { reactionJoint } from './mechForces';
import { MechForcesPanel } from './MechForcesPanel';

/** Props of MechanismPage: the app state and dispatch, and the solver client (null until it is made). */
export interface MechanismPageProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  client: JobRunner<MechanismJobs> | null;
  /** The query the app was opened with, to say why its mech= was refused; default none. */
  openedSearch?: string;
  /** In the embed (page=mech in embed.html or <fourbar-lab>): the linkage, Play and the plots only; default false. */
  embedded?: boolean;
  /** The embed's panels and lock (its URL's panels and lock=edit); default: drive and plots shown, editable. */
  embedOptions?: MechEmbedOptions;
  /** Makes the live stage (Play and a joint's drag drawn in a worker); default none: the page draws them itself. */
  createStage?: MechStageFactory;
}

/** What an embed of the page shows and locks: the drive row, the joints' positions, the plots; dragging joints. */
export interface MechEmbedOptions {
  driveShown: boolean;
  positionsShown: boolean;
  plotsShown: boolean;
  editLocked: boolean;
  /** The positions table's accessible name. */
  positionsLabel: string;
}

const EMBED_DEFAULTS: MechEmbedOptions = {
  driveShown: true,
  positionsShown: false,
  plotsShown: true,
  editLocked: false,
  positionsLabel: '',
};

/**
 * The mechanism page (機構): any planar linkage of pins and sliders (src/mechanism). The template gallery, the
 * canvas (drag a joint to move it as drawn, tap to place a new part), Play and the input, the editor, two plots
 * against the input and the exports. The template and the edited linkage live in the mech slice (URL tpl, mech);
 * the input, Play and the view are the page's own. A new template starts the page afresh (its key).
 */
export function MechanismPage(props: MechanismPageProps) {
  const { state, dispatch, client, embedded = false, openedSearch = '', embedOptions = EMBED_DEFAULTS } = props;
  // One stage for the page's life (a new template remounts the workspace, whose canvas the stage takes anew).
  const [live] = useState(() => props.createStage?.() ?? null);
  useEffect(() => () => live?.dispose(), [live]);
  const m = mechMessagesFor(state.shell.locale);
  const { template, spec: edited, forces } = state.mech;
  const { input, direction, speed, traced, plots, velocities } = state.mech;
  const settings = useMemo<MechPageSettings>(
    () => ({ input, direction, speed, traced, plots, velocities }),
    [input, direction, speed, traced, plots, velocities],
  );
  // The reason a link's mech= was refused (the shell's notice names the key; this says why), read once on arrival.
  const [refused, setRefused] = useState(() => linkRefusal(openedSearch));
  return (
    <div className={`mech${embedded ? ' mech-embedded' : ''}`} data-testid="mechanism-page">
      {!embedded && (
        <div className="mech-head">
          <h2 className="section-title">{m.pageTitle}</h2>
          <p className="note mech-intro">{m.intro}</p>
        </div>
      )}
      {refused && (
        <p className="mech-error mech-refused" role="alert" data-testid="mech-refused">
          {m.linkRefused(refused)}{' '}
          <button type="button" className="btn btn-small" onClick={() => setRefused(null)}>
            {m.dismiss}
          </button>
        </p>
      )}
      {!embedded && (
        <section className="mech-gallery-card" aria-label={m.galleryTitle}>
          <TemplateGallery
            current={template}
            edited={edited !== null}
            onOpen={(t) => dispatch({ type: 'setMechTemplate', template: t })}
            names={m.templateNames}
            label={m.galleryLabel}
          />
        </section>
      )}
      <MechWorkspace
        key={template}
        template={template}
        edited={edited}
        forces={forces}
        settings={settings}
        lengthUnit={state.design.lengthUnit}
        dispatch={dispatch}
        client={client}
        m={m}
        embedded={embedded}
        embedOptions={embedOptions}
        live={live}
      />
    </div>
  );
}

/** Why the mech= of a query is refused, or null (none, or a good one). */
function linkRefusal(search: string): string | null {
  const raw = new URLSearchParams(search).get('mech');
  if (raw === null) return null;
  const r = mechSpecCodec.parse(raw);
  return r.ok ? null : r.why;
}

/** Props of MechWorkspace. */
interface MechWorkspaceProps {
  template: MechTemplateKey;
  edited: MechanismSpec | null;
  forces: MechForcesSettings;
  /** The page's settings in the slice: the drive at rest, the traces, the plots, the velocity arrows. */
  settings: MechPageSettings;
  lengthUnit: LengthUnit;
  dispatch: Dispatch<Action>;
  client: JobRunner<MechanismJobs> | null;
  m: MechMessages;
  embedded: boolean;
  embedOptions: MechEmbedOptions;
  live: MechLiveStage | null;
}

/** Every joint and tracer over the run (and as drawn): the canvas fits this box, so Play does not move the view. */
function runBounds(a: MechAnalysis): Bounds {
  const b = emptyBounds();
  const pose = drawnPose(a.spec);
  for (const q of [...Object.values(pose.joints), ...Object.values(pose.points)]) extendBounds(b, q.x, q.y);
  if (a.sweep && a.run) {
    for (const id of [...a.spec.joints.map((j) => j.id), ...(a.spec.points ?? []).map((p) => p.id)]) {
      const { x, y } = pathOf(a.sweep, id, a.run);
      for (let i = 0; i < x.length; i++) if (Number.isFinite(x[i])) extendBounds(b, x[i], y[i]);
    }
  }
  return b;
}

/** Each slider's slide range over the run. */
function slideRanges(a: MechAnalysis): Record<string, [number, number]> {
  const out: Record<string, [number, number]> = {};
  if (!a.sweep || !a.run) return out;
  for (const j of a.spec.joints) {
    if (j.kind !== 'P') continue;
    const s = a.sweep.sliders[j.id].s.subarray(a.run[0], a.run[1] + 1);
    let lo = 0;
    let hi = 0;
    for (const v of s) if (Number.isFinite(v)) [lo, hi] = [Math.min(lo, v), Math.max(hi, v)];
    out[j.id] = [lo, hi];
  }
  return out;
}

/** The default traced points: every tracer. */
const defaultTraced = (spec: MechanismSpec) => (spec.points ?? []).map((p) => p.id);

/**
 * The page below the gallery, for one template (a new template remounts it; the slice sets the input to 0 and the
 * plots and traces to the defaults).
 */
function MechWorkspace(props: MechWorkspaceProps) {
  const { template, edited, forces, settings, lengthUnit, dispatch, client, m, embedded, embedOptions, live } = props;
  const locked = embedded && embedOptions.editLocked;
  const stored = edited ?? MECHANISM_TEMPLATES[template].spec;
  // A pointer drag draws its linkage (drag.shown) at every move and sweeps it (drag.analysed) when the pointer rests:
  // everything below but the canvas works on the analysed spec.
  const drag = useJointDrag(stored, (next) => dispatch({ type: 'setMechSpec', spec: next }));
  const spec = drag.analysed;
  const name = m.templateNames[template] ?? template;
  const shownName = edited ? m.edited(name) : name;
  // The rocking limits are refined once the edits settle (a deferred render), not at every move of a drag.
  const analysis = useMemo(() => analyseMechanism(spec, false), [spec]);
  const settled = useDeferredValue(analysis);
  const refined = useMemo(() => withRefinedLimits(settled), [settled]);
  const range = runRange(analysis);
  const kind = analysis.grid?.kind ?? 'R';
  const span = range ? range[1] - range[0] : 0;
  const rate = (speed: number) => (kind === 'R' ? degToRad(speed) : (speed * span) / 360);
  const setSettings = (patch: Partial<MechPageSettings>) => dispatch({ type: 'setMechPage', patch });
  const [playhead] = useState(createPlayheadSource);
  const { drive, setPlaying, step, setInput, reverse, setSpeed, stop } = useMechDrive(
    range,
    analysis.fullTurn,
    rate,
    settings,
    setSettings,
    playhead,
    live,
  );
  const clamp = (t: number) => (range ? Math.min(range[1], Math.max(range[0], t)) : 0);
  const at: PlayheadInput = { playhead, rest: drive.input, clamp };
  /** The input on screen now (Play's playhead or the committed input), for what is made at a click (exports). */
  const inputNow = () => clamp(playhead.get()?.input ?? drive.input);
  const [selected, setSelected] = useState<string | null>(null);
  const traced = useMemo(() => new Set(settings.traced ?? defaultTraced(spec)), [settings.traced, spec]);
  const setTraced = (change: (s: ReadonlySet<string>) => ReadonlySet<string>) =>
    setSettings({ traced: [...change(traced)] });
  const plots: readonly [MechPlotChoice, MechPlotChoice] = useMemo(
    () => settings.plots ?? defaultPlots(spec),
    [settings.plots, spec],
  );
  const setPlots = (change: (old: readonly [MechPlotChoice, MechPlotChoice]) => [MechPlotChoice, MechPlotChoice]) =>
    setSettings({ plots: change(plots) });
  const showVelocities = settings.velocities;
  const setShowVelocities = (velocities: boolean) => setSettings({ velocities });
  const [csvRates, setCsvRates] = useState(false);
  const [placing, setPlacing] = useState<PlaceKind | null>(null);
  const [editError, setEditError] = useState<string | null>(null);
  const [exportNote, setExportNote] = useState<string | null>(null);
  const [frozenBounds, setFrozenBounds] = useState<Bounds | null>(null);
  const [newLinks, setNewLinks] = useState<[string, string]>(() => {
    const moving = spec.links.filter((l) => l !== GROUND);
    return [GROUND, moving[0] ?? GROUND];
  });
  const viewRef = useRef<{ width: number; height: number; offset: ViewOffset } | null>(null);
  const liveBounds = useMemo(() => runBounds(analysis), [analysis]);
  const bounds = frozenBounds ?? liveBounds;

  const edit = (change: (s: MechanismSpec) => MechanismSpec) => {
    try {
      const next = change(spec);
      setEditError(null);
      if (next !== spec) dispatch({ type: 'setMechSpec', spec: next });
    } catch (e) {
      setEditError(m.editRefused((e as Error).message));
    }
  };

  // The rates (the plots' speeds and accelerations, the velocity arrows) come from the worker, for this spec.
  const plotChoicesParsed = plots.map((c) => parseChoice(spec, c));
  const wantRates = showVelocities || plotChoicesParsed.some((c) => c && needsRates(c.kind));
  const { enabled: forcesOn, rhoKgPerM, gravityMPerS2, inputSpeed } = forces;
  const forceJob = useMemo<MechForcesJob | null>(
    () => (forcesOn ? { metresPerUnit: METRES_PER_UNIT[lengthUnit], rhoKgPerM, gravityMPerS2, inputSpeed } : null),
    [forcesOn, lengthUnit, rhoKgPerM, gravityMPerS2, inputSpeed],
  );
  const solved = useMechSweepJob(client, analysis, wantRates, forceJob);
  const rateSweep = solved.rates;
  const forceJoint = reactionJoint(spec, forces.joint);
  const valueNow = (values: ArrayLike<number> | undefined, input: number) =>
    values ? valueAt(analysis, values, input) : NaN;
  const reactionSeries = solved.forces?.joints[forceJoint];

  const traces = useMemo(
    () =>
      analysis.sweep && analysis.run
        ? [...traced]
            .filter((id) => analysis.sweep!.joints[id] || analysis.sweep!.points[id])
            .map((id) => ({ id, ...pathOf(analysis.sweep!, id, analysis.run!) }))
        : [],
    [analysis, traced],
  );
  const slideRange = useMemo(() => slideRanges(analysis), [analysis]);
  // What the canvas draws at any input (the page's and the live stage's): the arrows are off while a joint is dragged.
  const arrowsOn = !drag.dragging;
  const forceSeries = arrowsOn && forcesOn && forces.arrows ? solved.forces : null;
  const scene = useMemo<MechScene>(() => {
    const velocities: MechSeriesAt[] = [];
    if (showVelocities && rateSweep && arrowsOn) {
      for (const id of [...spec.joints.map((j) => j.id), ...(spec.points ?? []).map((p) => p.id)]) {
        const s = rateSweep.joints[id] ?? rateSweep.points[id];
        if (s?.vx && s.vy) velocities.push({ id, x: s.vx, y: s.vy });
      }
    }
    const reactions: MechSeriesAt[] = [];
    for (const j of forceSeries ? spec.joints : []) {
      const r = forceSeries!.joints[j.id];
      if (r) reactions.push({ id: j.id, x: r.fx, y: r.fy });
    }
    const runs = !analysis.problem && analysis.grid && analysis.sweep;
    return {
      spec,
      grid: runs ? analysis.grid : null,
      sweep: runs ? analysis.sweep : null,
      traces,
      slideRange,
      selected,
      velocities,
      forces: reactions,
      faint: analysis.problem !== null,
    };
  }, [spec, analysis, traces, slideRange, selected, showVelocities, rateSweep, arrowsOn, forceSeries]);
  /** The pose at an input (the committed linkage's). */
  const poseAtInput = (input: number) => mechPictureAt(scene, input).pose;

  const inputJoint = spec.input.joint;
  const inputText = (t: number) => (kind === 'R' ? `${formatNumber(radToDeg(t), 4)}°` : formatNumber(t, 4));
  const status = statusText(refined.spec === spec ? refined : analysis, m, inputText);
  const limitText = drive.limitAt !== null && drive.playing ? m.atLimit(inputText(drive.limitAt)) : null;

  const place = (kindToPlace: PlaceKind, at: Pt) => {
    try {
      const [a, b] = newLinks;
      const r =
        kindToPlace === 'T'
          ? addTracer(spec, a === GROUND ? b : a, at.x, at.y)
          : addJoint(spec, kindToPlace, [a, b], at.x, at.y);
      dispatch({ type: 'setMechSpec', spec: r.spec });
      setSelected(r.id);
      if (kindToPlace === 'T') setTraced((s) => new Set([...s, r.id]));
      setEditError(null);
    } catch (e) {
      setEditError(m.editRefused((e as Error).message));
    }
    setPlacing(null);
  };
  const centre = (): Pt => ({ x: (bounds.minX + bounds.maxX) / 2 || 0, y: (bounds.minY + bounds.maxY) / 2 || 0 });

  const exportPicture = (format: 'png' | 'svg') => {
    const view = viewRef.current;
    if (!view || view.width <= 0) return;
    const picture = mechPictureAt(scene, inputNow(), drag.shown.get());
    const draw = (ctx: Parameters<typeof drawMechanism>[0], v: ViewTransform) => drawMechanism(ctx, picture, v);
    const v = fitView(bounds, view.width, view.height, view.offset);
    const fileBase = `mechanism_${templateUrlValue(template)}${edited ? '_edited' : ''}`;
    if (format === 'svg') exportDrawingSvg((ctx) => draw(ctx, v), view.width, view.height, fileBase);
    else void exportDrawingPng((ctx) => draw(ctx, v), view.width, view.height, fileBase);
  };
  const exportCsv = async () => {
    if (!range || !analysis.grid) return;
    setExportNote(m.exportBusy);
    try {
      const inputs = csvInputs(analysis.grid.kind, range, analysis.fullTurn);
      const params = { spec, inputs, rates: csvRates };
      const sweep = client
        ? await client.run('mechSweep', params, { channel: 'mechCsv' }).result
        : sweepMechanism(spec, inputs, csvRates ? { omega: 1, alpha: 0 } : undefined);
      if (!sweep) return;
      const fileBase = `mechanism_${templateUrlValue(template)}${edited ? '_edited' : ''}`;
      downloadText(mechCsv(spec, inputs, sweep, csvRates), `${fileBase}.csv`, 'text/csv');
      setExportNote(null);
    } catch (e) {
      setExportNote(m.exportFailed((e as Error).message));
    }
  };

  const xDeg = useMemo(
    () => (analysis.grid ? analysis.grid.inputs.map((t) => (kind === 'R' ? radToDeg(t) : t)) : new Float64Array(0)),
    [analysis, kind],
  );
  const xLabel = kind === 'R' ? m.axisInputDeg : m.axisInputLength;
  const forceX = useMemo(
    () => (analysis.run ? xDeg.subarray(analysis.run[0], analysis.run[1] + 1) : xDeg),
    [analysis, xDeg],
  );
  // The plots' series change with the linkage and its rates, not with the input: kept while Play moves only the
  // markers, so a frame redraws two markers rather than two charts.
  const plotSeries = useMemo(
    () =>
      plots.map((choice, n) => {
        const c = parseChoice(spec, choice);
        const source = c && (needsRates(c.kind) ? rateSweep : analysis.sweep);
        const title = c ? choiceLabel(c, m) : m.plotNone;
        let data: XYChartData = { series: [] };
        let line: { y: Float64Array; color: string } | null = null;
        if (c && source && analysis.run && !analysis.problem) {
          const y = plotValues(c, source);
          const [a, b] = analysis.run;
          const color = c.kind === 'angle' ? linkColor(spec, c.id) : c.kind === 'accel' ? '#be185d' : '#0e7490';
          data = { series: [{ label: title, color, x: xDeg.subarray(a, b + 1), y: y.subarray(a, b + 1) }] };
          line = { y, color };
        }
        const texts = { title, xLabel, yLabel: c ? axisLabel(c.kind, kind, m) : '' };
        return { n: n + 1, choice, c, data, line, texts, pending: c !== null && source === null && !analysis.problem };
      }),
    [plots, spec, rateSweep, analysis, xDeg, xLabel, kind, m],
  );
  const xOf = (input: number) => (kind === 'R' ? radToDeg(input) : input);
  const plotViews = plotSeries.map(({ line, ...p }) => {
    const markerAt = (input: number): MarkerAt | null =>
      line ? { x: xOf(input), dots: [{ y: valueAt(analysis, line.y, input), color: line.color }] } : null;
    return { ...p, markerAt };
  });
  const choiceOptions = useMemo(
    () => plotChoices(spec).map((c) => ({ value: c, label: choiceLabel(parseChoice(spec, c)!, m) })),
    [spec, m],
  );
  const exportPlot = async (n: number, format: 'png' | 'svg') => {
    const p = plotViews[n - 1];
    const chart = { draw: specDrawing(xySpec(), p.texts, p.data, p.markerAt(inputNow())), width: 640, height: 360 };
    const fileBase = `mechanism_${templateUrlValue(template)}_plot${n}`;
    if (format === 'svg') downloadText(exportChart(chart, 'svg'), `${fileBase}.svg`, 'image/svg+xml');
    else downloadPng(await exportChart(chart, '2x'), `${fileBase}.png`);
  };

  const sliderMin = range ? (kind === 'R' ? radToDeg(range[0]) : range[0]) : 0;
  const sliderMax = range ? (kind === 'R' ? radToDeg(range[1]) : range[1]) : 0;
  const sliderStep = kind === 'R' ? 1 : span / 360 || 0.01;
  const canRun = range !== null;

  // The editor (a table of every joint's fields) re-renders when what it shows changes, not at each frame of Play:
  // its callbacks read only the values listed (the setters and stop are the page's own and stable in effect).
  const editor = useMemo(
    () => (
      <SpecEditor
        spec={spec}
        edit={edit}
        selected={selected}
        onSelect={setSelected}
        traced={traced}
        onTrace={(id, on) =>
          setTraced((s) => {
            const next = new Set(s);
            if (on) next.add(id);
            else next.delete(id);
            return next;
          })
        }
        newLinks={[
          spec.links.includes(newLinks[0]) ? newLinks[0] : GROUND,
          spec.links.includes(newLinks[1]) ? newLinks[1] : GROUND,
        ]}
        onNewLinks={setNewLinks}
        onPlace={(k, byKeyboard) => (byKeyboard ? place(k, centre()) : setPlacing(k))}
        onNew={() => {
          stop(0);
          setSelected(null);
          dispatch({ type: 'setMechSpec', spec: emptySpec() });
          setNewLinks([GROUND, GROUND]);
        }}
        onResetTemplate={edited ? () => dispatch({ type: 'setMechSpec', spec: null }) : null}
        onAddLink={() => {
          const r = addLink(spec);
          dispatch({ type: 'setMechSpec', spec: r.spec });
          setNewLinks(([, b]) => [spec.links.includes(b) ? b : GROUND, r.name]);
        }}
        m={m}
      />
    ),
    // eslint-disable-next-line react-hooks/exhaustive-deps
    [spec, selected, traced, newLinks[0], newLinks[1], bounds, edited, m, dispatch],
  );

  return (
    <div
      className="mech-workspace"
      data-mech-state={analysis.problem ? analysis.problem.code : 'ok'}
      data-trace={traceDigest(traces)}
    >
      <div className="mech-stage-col">
        <div className="mech-stage-head">
          <h3 className="mech-name-title">{shownName}</h3>
          {locked && (
            <span className="mech-locked" title={m.editLockedHint} data-testid="mech-edit-locked">
              {m.editLocked}
            </span>
          )}
          <span className={`mech-mobility ${analysis.mobility === 1 ? 'is-ok' : 'is-bad'}`} data-testid="mech-mobility">
            {m.mobility(Number.isFinite(analysis.mobility) ? String(analysis.mobility) : '—')}
          </span>
        </div>
        <MechStage
          at={at}
          scene={scene}
          dragged={drag.shown}
          live={live}
          bounds={bounds}
          label={locked ? m.canvasLabelLocked(shownName) : m.canvasLabel(shownName)}
          labels={{ zoomIn: m.zoomIn, zoomOut: m.zoomOut, resetView: m.resetView }}
          viewRef={viewRef}
          onGrab={(id) => {
            if (locked) return;
            if (id) {
              stop(0);
              setSelected(id);
              setFrozenBounds(liveBounds);
              drag.start();
            } else {
              drag.end();
              setFrozenBounds(null);
            }
          }}
          onDrag={(id, p) => {
            if (locked) return;
            try {
              drag.move((s) => moveJoint(s, id, p.x, p.y));
              if (editError !== null) setEditError(null);
            } catch (e) {
              setEditError(m.editRefused((e as Error).message));
            }
          }}
          placing={placing !== null}
          onTap={(p) => placing && place(placing, p)}
          onNudge={(dx, dy) => {
            if (!selected || locked) return;
            const j = spec.joints.find((x) => x.id === selected) ?? spec.points?.find((x) => x.id === selected);
            if (j) edit((s) => moveJoint(s, selected, j.x + dx, j.y + dy));
          }}
        />
        <p className={`mech-status${analysis.problem ? ' is-bad' : ''}`} role="status" data-testid="mech-status">
          {limitText ?? status}
        </p>
        {placing && (
          <p className="mech-placing" role="status">
            {m.placeHint(m.placeWhat[placing])}{' '}
            <button type="button" className="btn btn-small" onClick={() => setPlacing(null)}>
              {m.cancel}
            </button>
          </p>
        )}
        {editError && (
          <p className="mech-error" role="alert">
            {editError}
          </p>
        )}
        <div className="mech-drive" role="group" aria-label={m.play} hidden={embedded && !embedOptions.driveShown}>
          <button
            type="button"
            className="btn btn-primary mech-play"
            disabled={!canRun}
            aria-pressed={drive.playing}
            onClick={() => setPlaying(!drive.playing)}
          >
            {drive.playing ? m.pause : m.play}
          </button>
          <button
            type="button"
            className="btn"
            disabled={!canRun}
            onClick={() => step(kind === 'R' ? degToRad(1) : span / 360)}
          >
            {m.step}
          </button>
          <button type="button" className="btn" disabled={!canRun} aria-pressed={drive.direction < 0} onClick={reverse}>
            {m.reverse}
          </button>
          <AtPlayhead at={at}>
            {(input) => (
              <label className="mech-input">
                <span>{kind === 'R' ? m.inputAngle(inputJoint || '—') : m.inputSlide(inputJoint || '—')}</span>
                <input
                  type="range"
                  min={sliderMin}
                  max={sliderMax}
                  step={sliderStep}
                  value={xOf(input)}
                  disabled={!canRun}
                  onChange={(e) => {
                    const v = Number(e.target.value);
                    setInput(kind === 'R' ? degToRad(v) : v);
                  }}
                />
                <output data-testid="mech-input-value">{inputText(input)}</output>
              </label>
            )}
          </AtPlayhead>
          <label className="mech-speed">
            <span>{m.speed}</span>
            <input
              type="range"
              min={5}
              max={360}
              step={5}
              value={drive.speed}
              onChange={(e) => setSpeed(Number(e.target.value))}
            />
            <output>
              {drive.speed} {m.speedUnit}
            </output>
          </label>
        </div>
        {embedded && embedOptions.positionsShown && (
          <AtPlayhead at={at}>
            {(input) => <MechPositions spec={spec} pose={poseAtInput(input)} label={embedOptions.positionsLabel} />}
          </AtPlayhead>
        )}
      </div>
      <div className="mech-side" hidden={embedded}>
        <section className="mech-card" aria-label={m.editTitle}>
          <h3 className="mech-card-title">{m.editTitle}</h3>
          {editor}
        </section>
      </div>
      <section className="mech-plots" aria-label={m.plotsTitle} hidden={embedded && !embedOptions.plotsShown}>
        <div className="mech-plot-controls">
          {plotViews.map((p) => (
            <label key={p.n}>
              {m.plotChoice(p.n)}{' '}
              <select
                value={p.c ? p.choice : ''}
                onChange={(e) => setPlots((old) => (p.n === 1 ? [e.target.value, old[1]] : [old[0], e.target.value]))}
              >
                <option value="">{m.plotNone}</option>
                {choiceOptions.map((o) => (
                  <option key={o.value} value={o.value}>
                    {o.label}
                  </option>
                ))}
              </select>
            </label>
          ))}
          <label className="mech-check">
            <input type="checkbox" checked={showVelocities} onChange={(e) => setShowVelocities(e.target.checked)} />{' '}
            {m.showVelocities}
          </label>
        </div>
        <div className="mech-charts">
          {plotViews.map((p) => (
            <MechPlotCell
              key={p.n}
              at={at}
              data={p.data}
              texts={p.texts}
              markerAt={p.markerAt}
              testId={`mech-chart-${p.n}`}
              note={p.pending && <p className="note">{m.ratesPending}</p>}
            />
          ))}
        </div>
      </section>
      {(!embedded || forces.enabled) && (
        <AtPlayhead at={at} everyFrame={forcesOn}>
          {(input) => (
            <MechForcesPanel
              spec={spec}
              settings={forces}
              joint={forceJoint}
              kind={kind}
              lengthUnit={lengthUnit}
              forces={solved.forces}
              pending={solved.pending}
              error={solved.error}
              x={forceX}
              run={analysis.problem ? null : analysis.run}
              xNow={xOf(input)}
              effortNow={valueNow(solved.forces?.input, input)}
              reactionNow={{ fx: valueNow(reactionSeries?.fx, input), fy: valueNow(reactionSeries?.fy, input) }}
              dispatch={dispatch}
              m={m}
            />
          )}
        </AtPlayhead>
      )}
      <section className="mech-exports" aria-label={m.exportsTitle} hidden={embedded}>
        <h3 className="mech-card-title">{m.exportsTitle}</h3>
        <div className="mech-export-row">
          <button type="button" className="btn btn-small" disabled={!canRun} onClick={() => void exportCsv()}>
            {m.exportCsv}
          </button>
          <label className="mech-check">
            <input type="checkbox" checked={csvRates} onChange={(e) => setCsvRates(e.target.checked)} /> {m.csvRates}
          </label>
          <button type="button" className="btn btn-small" onClick={() => exportPicture('png')}>
            {m.exportPng}
          </button>
          <button type="button" className="btn btn-small" onClick={() => exportPicture('svg')}>
            {m.exportSvg}
          </button>
          {plotViews.map((p) => (
            <span key={p.n} className="mech-export-pair">
              <button type="button" className="btn btn-small" onClick={() => void exportPlot(p.n, 'png')}>
                {m.exportPlotPng(p.n)}
              </button>
              <button type="button" className="btn btn-small" onClick={() => void exportPlot(p.n, 'svg')}>
                {m.exportPlotSvg(p.n)}
              </button>
            </span>
          ))}
        </div>
        {exportNote && (
          <p className="note" role="status">
            {exportNote}
          </p>
        )}
      </section>
    </div>
  );
}

/** A short fingerprint of the traced paths (their points' sum, 6 digits), for tests to see a curve change. */
function traceDigest(traces: { x: ArrayLike<number>; y: ArrayLike<number> }[]): string {
  let sum = 0;
  for (const t of traces) for (let i = 0; i < t.x.length; i++) if (Number.isFinite(t.x[i])) sum += t.x[i] + 2 * t.y[i];
  return sum.toPrecision(6);
}

/** The status line: what stops the linkage, or how its input moves. */
function statusText(a: MechAnalysis, m: MechMessages, inputText: (t: number) => string): string {
  const p = a.problem;
  if (p?.code === 'noInput') return m.noInput;
  if (p?.code === 'mobility') return p.mobility > 1 ? m.mobilityHelp.high(p.mobility) : m.mobilityHelp.low(p.mobility);
  if (p?.code === 'invalid') return m.invalid(p.detail);
  if (p?.code === 'singular') return m.singular;
  if (a.fullTurn) return m.fullTurn;
  const r = a.limits;
  return r ? m.rocking(inputText(r[0]), inputText(r[1])) : '';
}
