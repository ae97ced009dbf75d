import { useMemo, useState } from 'react';
import { TWO_PI } from '../../../solver/angles';
import type { Point } from '../../../solver/kinematics';
import { downloadText } from '../../../shared/canvas/download';
import { formatSci } from '../../../shared/format';
import { useMessages } from '../../../shared/i18n/MessagesContext';
import type { PlacedJoints } from '../../../synthesis/types';
import type { DrawContext } from '../../../shared/canvas/drawContext';
import type { ViewTransform } from '../../../shared/canvas/view';
import { RECHECK_TOL } from '../../../synthesis/ninePoint/ninePointSynthesis';
import type { SynthesisModeProps } from '../openDesign';
import { synthesisMessagesFor } from '../synthesisMessages';
import type { DesignChoice } from '../path/ChosenDesign';
import { ChosenDesign } from '../path/ChosenDesign';
import type { MotionRange } from '../path/candidateFacts';
import { couplerCurve } from '../path/candidateFacts';
import type { PathCurve } from '../path/drawPathScene';
import { pathSceneBounds } from '../path/drawPathScene';
import { targetsExtent } from '../path/pathTaskOf';
import { TargetCanvas } from '../path/TargetCanvas';
import { TargetsCard } from '../path/TargetsCard';
import { useFitBounds } from '../path/useFitBounds';
import type { SynthesisPool } from '../path/usePathSynthesis';
import { lastPathRun } from '../path/usePathSynthesis';
import { useTargetEditing } from '../path/useTargetEditing';
import { NineClassList } from './NineClassList';
import { cognateFollowers, cognatePoses, drawCognatePoses } from './nineCognates';
import type { NineFilters } from './nineClassFacts';
import { NO_FILTERS, cognateDesign, filterClasses, nineClassFacts } from './nineClassFacts';
import { ninePointCsv } from './nineCsv';
import { ninePointMessagesFor } from './ninePointMessages';
import { nineRefusalText } from './nineInput';
import { WMS_PROBLEM_3 } from './wmsProblem3';
import { NineRunControls } from './NineRunControls';
import { useNinePointSynthesis } from './useNinePointSynthesis';
import { SynthesisPrint } from '../print/SynthesisPrint';
import { ninePrintContent } from '../path/pathPrint';

/** Props of NinePointMode: a mode's props and how to make the pool of solver workers. */
export interface NinePointModeProps extends SynthesisModeProps {
  createPool: () => SynthesisPool;
}

const BRANCHES = ['open', 'crossed'] as const;
const FULL_TURN: MotionRange = { full: true, lo: 0, hi: TWO_PI };
/** Samples of the whole coupler curve drawn (each assembly). */
const CURVE_SAMPLES = 720;

function samePoints(a: readonly Point[], b: readonly Point[]): boolean {
  return a.length === b.length && a.every((p, i) => p.x === b[i].x && p.y === b[i].y);
}

/**
 * The Nine points mode (九點精確合成): exactly nine targets (canvas, text area, table, as the Path mode), "Find every
 * linkage" on the worker pool with progress and Cancel, every real class found with filters and thumbnails, the
 * chosen class's cognates moving through the points, "Open in simulator" and the exports.
 */
export function NinePointMode({ state, dispatch, onOpen, createPool }: NinePointModeProps) {
  const st = synthesisMessagesFor(state.shell.locale);
  const nt = ninePointMessagesFor(state.shell.locale);
  const t = useMessages();
  const s = state.synPath;
  const run = useNinePointSynthesis(createPool);
  const { selected, setSelected, view, setView, replaced, replace, canvasRef, ...edit } = useTargetEditing(
    s.targets,
    dispatch,
    st,
  );
  const [filters, setFilters] = useState<NineFilters>(NO_FILTERS);
  const [chosenClass, setChosenClass] = useState(0);
  const [shownCognate, setShownCognate] = useState(0);

  const points = run.points ?? s.targets;
  const size = targetsExtent(points).size;
  const classes = useMemo(() => run.result?.classes ?? [], [run.result]);
  const facts = useMemo(() => classes.map((c) => nineClassFacts(c, size)), [classes, size]);
  const shown = useMemo(() => filterClasses(classes, facts, filters), [classes, facts, filters]);
  const chosen = shown.includes(chosenClass) ? chosenClass : (shown[0] ?? -1);
  const cls = chosen >= 0 ? classes[chosen] : null;
  const choices: (DesignChoice & { theta2: number })[] = useMemo(
    () =>
      cls
        ? cls.cognates.map((d, k) => ({
            design: cognateDesign(d),
            facts: facts[chosen].cognates[k],
            theta2: d.theta2[0],
          }))
        : [],
    [cls, facts, chosen],
  );
  const choice = choices[Math.min(shownCognate, choices.length - 1)] ?? null;
  const refusal = nineRefusalText(s.targets, nt);

  // The whole coupler curve, both assemblies over a full turn: the points may lie on either (a circuit or branch
  // defect), and every one of the nine is on it. The assembly the linkage moves on is drawn strong.
  const curves: PathCurve[] = useMemo(
    () =>
      choice
        ? BRANCHES.map((b) => ({
            ...couplerCurve({ ...choice.design, branch: b }, FULL_TURN, CURVE_SAMPLES),
            faint: b !== choice.design.branch,
          }))
        : [],
    [choice],
  );
  const moving = choice ? { design: choice.design, motion: choice.facts.motion } : null;
  // The class's other cognates move with it, their coupler points on its own.
  const shownIdx = Math.min(shownCognate, choices.length - 1);
  const drawMoving = useMemo(() => {
    const followers = cls && shownIdx >= 0 ? cognateFollowers(cls.cognates[shownIdx], cls.cognates) : [];
    return followers.length > 0
      ? (ctx: DrawContext, v: ViewTransform, pose: PlacedJoints) =>
          drawCognatePoses(ctx, v, cognatePoses(pose, followers))
      : undefined;
  }, [cls, shownIdx]);
  const content = pathSceneBounds({
    targets: s.targets,
    curves: curves.filter((c) => !c.faint),
    pose: null,
    design: choice?.design ?? null,
  });
  const bounds = useFitBounds(content, `${replaced}|${run.elapsedMs}|${chosen}|${shownCognate}`);

  // The optimiser's answer for the same nine points, when the Path mode has one that misses them.
  const pathRun = lastPathRun();
  const best = pathRun.solutions?.[0];
  const optimiserMiss =
    classes.length > 0 &&
    best &&
    pathRun.task &&
    samePoints(pathRun.task.targets, points) &&
    best.maxDistance > RECHECK_TOL * size
      ? best.maxDistance
      : null;

  return (
    <div className="syn-path nine-mode" data-testid="nine-mode">
      <p className="note syn-intro">{nt.intro}</p>
      <div className="syn-stage card">
        <TargetCanvas
          targets={s.targets}
          selected={selected}
          curves={curves}
          moving={moving}
          drawMoving={drawMoving}
          bounds={bounds}
          view={view}
          onViewChange={setView}
          onSelect={setSelected}
          onMove={edit.onMove}
          onAdd={edit.onAdd}
          onRemove={edit.onRemove}
          canvasRef={canvasRef}
          st={st}
        />
      </div>
      <div className="syn-side">
        <TargetsCard
          s={{ ...s, timing: 'free' }}
          selected={selected}
          onSelect={setSelected}
          onReplace={(targets) => replace(targets)}
          dispatch={dispatch}
          st={st}
        />
        <div className="syn-buttons">
          <button type="button" className="btn" onClick={() => replace(WMS_PROBLEM_3)}>
            {nt.exampleProblem3}
          </button>
        </div>
        <NineRunControls
          run={run}
          refusal={refusal}
          onRun={() => {
            setChosenClass(0);
            setShownCognate(0);
            void run.run(s.targets);
          }}
          onCancel={run.cancel}
          nt={nt}
        />
        {optimiserMiss !== null ? (
          <p className="note nine-compare" data-testid="nine-compare">
            {nt.optimiserWorse(formatSci(optimiserMiss, 3))}
          </p>
        ) : null}
        {run.result ? (
          <NineClassList
            classes={classes}
            facts={facts}
            shown={shown}
            points={points}
            filters={filters}
            onFilters={setFilters}
            chosen={chosen}
            onChoose={(i) => {
              setChosenClass(i);
              setShownCognate(0);
              // On a phone the canvas is above the list: bring the chosen class into view (a no-op when it shows).
              canvasRef.current?.scrollIntoView({ block: 'nearest', behavior: 'smooth' });
            }}
            nt={nt}
            st={st}
            t={t}
          />
        ) : null}
        {choice ? (
          <ChosenDesign
            choices={choices}
            shown={Math.min(shownCognate, choices.length - 1)}
            onShow={setShownCognate}
            stale={run.points !== null && run.points !== undefined && !samePoints(run.points, s.targets)}
            onOpen={() => onOpen({ design: choice.design, markers: points, theta2: choice.theta2 })}
            onExportCsv={() => downloadText(ninePointCsv(classes), 'nine-point-classes.csv', 'text/csv;charset=utf-8')}
            {...edit.sceneExports(bounds, curves, choice)}
            st={st}
            t={t}
          />
        ) : null}
      </div>
      <SynthesisPrint
        m={st.print}
        build={() =>
          ninePrintContent({
            targets: s.targets,
            unit: state.design.lengthUnit,
            rank: chosen,
            choices,
            passes: (cls?.cognates ?? []).map((d) =>
              d.theta2.map((theta2, i) => ({ design: { ...d, branch: d.branches[i] ?? d.branch }, theta2 })),
            ),
            shown: shownIdx,
            stale: run.points !== null && run.points !== undefined && !samePoints(run.points, s.targets),
            curve: curves.find((c) => !c.faint) ?? null,
            st,
            t,
            mode: st.modeNine,
            className: nt.className(chosen + 1),
          })
        }
      />
    </div>
  );
}
