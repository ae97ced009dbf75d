import { useCallback, useMemo, useRef, useState } from 'react';
import { radToDeg } from '../../../solver/angles';
import type { Point } from '../../../solver/kinematics';
import { robertsCognates } from '../../../synthesis/cognates';
import { placedJoints } from '../../../synthesis/placed';
import type { PlacedFourBar } from '../../../synthesis/types';
import { fitView } from '../../../shared/canvas/view';
import { formatNumber } from '../../../shared/format';
import { useMessages } from '../../../shared/i18n/MessagesContext';
import type { SynPathState, ViewOffset } from '../../../shared/state/appState';
import type { SynthesisModeProps } from '../openDesign';
import type { SynthesisMessages } from '../synthesisMessages';
import { synthesisMessagesFor } from '../synthesisMessages';
import { CandidateList } from './CandidateList';
import { placedFourBarFacts } from './candidateFacts';
import type { RankedCandidates } from './rankCandidates';
import { rankCandidates } from './rankCandidates';
import type { DesignChoice } from './ChosenDesign';
import { ChosenDesign } from './ChosenDesign';
import type { PathCurve, PathScene } from './drawPathScene';
import { pathSceneBounds } from './drawPathScene';
import { exportPathPng, exportPathSvg, exportResultsCsv } from './pathExports';
import { pathTaskOf, samePathTask, targetsExtent } from './pathTaskOf';
import type { PathTaskReason } from './pathTaskChecks';
import { missingTheta2, noneClose, pathTaskReasons } from './pathTaskChecks';
import { RunControls } from './RunControls';
import { TargetCanvas } from './TargetCanvas';
import { TargetsCard } from './TargetsCard';
import { TaskSettings } from './TaskSettings';
import { useFitBounds } from './useFitBounds';
import type { SynthesisPool } from './usePathSynthesis';
import { usePathSynthesis } from './usePathSynthesis';

/** Props of PathMode: a mode's props and how to make the pool of solver workers. */
export interface PathModeProps extends SynthesisModeProps {
  createPool: () => SynthesisPool;
}

/**
 * The answers as listed (rankCandidates), the candidate chosen and its cognates, each with the θ2 it passes the
 * first target at.
 */
function useChoices(
  run: ReturnType<typeof usePathSynthesis>,
  chosen: number,
): { choices: (DesignChoice & { theta2: number })[] } & RankedCandidates {
  const size = targetsExtent(run.task?.targets ?? []).size;
  const ranked = useMemo(() => rankCandidates(run.solutions ?? [], size), [run.solutions, size]);
  const { solutions, facts } = ranked;
  const choices = useMemo(() => {
    const sol = solutions?.[chosen];
    if (!sol) return [];
    const first = { design: sol.design, facts: facts[chosen], theta2: sol.theta2[0] ?? 0 };
    let cognates: { design: PlacedFourBar; theta2: number }[] = [];
    try {
      cognates = robertsCognates(sol.design, first.theta2);
    } catch {
      // A coupler point at a pin has no cognates with positive links: offer the candidate alone.
    }
    return [
      first,
      ...cognates.map((c) => ({ ...c, facts: placedFourBarFacts(c.design, c.theta2, sol.maxDistance, size) })),
    ];
  }, [solutions, chosen, facts, size]);
  return { choices, ...ranked };
}

/** A reason a task cannot be met, in words. */
function reasonText(r: PathTaskReason, st: SynthesisMessages): string {
  const n = (x: number) => formatNumber(x, 4);
  switch (r.kind) {
    case 'span':
      return st.reasonSpan(n(r.reach), n(r.span));
    case 'pivot-far':
      return st.reasonPivotFar(st.targetName(r.target), n(r.distance), n(r.reach));
    case 'same-theta2':
      return st.reasonSameTheta2(st.targetName(r.a), st.targetName(r.b), formatNumber(radToDeg(r.theta2), 6));
  }
}

/** Why Synthesize waits: fields in error (by name), or a target without its given θ2; null when it may run. */
function holdText(fieldErrors: ReadonlyMap<string, string>, s: SynPathState, st: SynthesisMessages): string | null {
  if (fieldErrors.size > 0) return st.fieldsInError([...fieldErrors.keys()].join(', '));
  const missing = missingTheta2(s);
  return missing === null ? null : st.missingTheta2(st.targetName(missing));
}

/**
 * The Path mode: the targets on a canvas, in a text area and a table; timing, bounds and input; Synthesize on a pool
 * of workers with progress and Cancel; the candidates; the chosen one (or a cognate) moving through the targets,
 * "Open in simulator" and the exports.
 */
export function PathMode({ state, dispatch, onOpen, createPool }: PathModeProps) {
  const st = synthesisMessagesFor(state.shell.locale);
  const t = useMessages();
  const s = state.synPath;
  const run = usePathSynthesis(createPool);
  const [selected, setSelected] = useState<number | null>(null);
  const [view, setView] = useState<ViewOffset>({ zoom: 1, panX: 0, panY: 0 });
  const [shown, setShown] = useState(0);
  const [replaced, setReplaced] = useState(0);
  const [fieldErrors, setFieldErrors] = useState<ReadonlyMap<string, string>>(new Map());
  const onFieldError = useCallback((name: string, error: string | null) => {
    setFieldErrors((m) => {
      if ((m.get(name) ?? null) === error) return m;
      const next = new Map(m);
      if (error === null) next.delete(name);
      else next.set(name, error);
      return next;
    });
  }, []);
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const chosen = Math.min(s.chosen, Math.max(0, (run.solutions?.length ?? 0) - 1));
  const { choices, solutions, facts, cognateOf } = useChoices(run, chosen);
  const choice = choices[Math.min(shown, choices.length - 1)] ?? null;
  const task = useMemo(() => pathTaskOf(s), [s]);
  // The answers belong to the task they were computed for: after an edit they are drawn faint and not opened.
  const stale = run.task !== null && !samePathTask(run.task, task);
  const hold = holdText(fieldErrors, s, st);
  const finished = run.status === 'done' || run.status === 'stopped';
  const summary = useMemo(() => {
    if (!finished || stale || !run.task || !run.solutions || !noneClose(run.task, run.solutions)) return null;
    const why = pathTaskReasons(run.task).map((r) => reasonText(r, st));
    const size = formatNumber(targetsExtent(run.task.targets).size, 4);
    return [st.noFit(size), ...(why.length > 0 ? why : [st.reasonUnknown])].join(' ');
  }, [finished, stale, run.task, run.solutions, st]);

  const curves: PathCurve[] = choice
    ? choices.map((c) => ({ x: c.facts.curve.x, y: c.facts.curve.y, faint: stale || c !== choice }))
    : [];
  const moving = choice && !stale ? { design: choice.design, motion: choice.facts.motion } : null;
  const content = pathSceneBounds({
    targets: s.targets,
    curves: choice ? [curves[Math.min(shown, curves.length - 1)]] : [],
    pose: null,
    design: choice?.design ?? null,
  });
  const bounds = useFitBounds(content, `${replaced}|${run.elapsedMs}|${chosen}|${shown}`);

  const replace = (targets: Point[], theta2Deg: number[] | null) => {
    dispatch({ type: 'setTargets', targets });
    if (theta2Deg) {
      dispatch({ type: 'setGivenTheta2', theta2Deg });
      dispatch({ type: 'setTiming', timing: 'given' });
    }
    setSelected(null);
    setReplaced((n) => n + 1);
    setView({ zoom: 1, panX: 0, panY: 0 });
  };
  const exportScene = (): { scene: PathScene; view: ReturnType<typeof fitView> } | null => {
    const canvas = canvasRef.current;
    if (!canvas) return null;
    const v = fitView(bounds, canvas.clientWidth, canvas.clientHeight, view);
    const pose = choice ? placedJoints(choice.design, choice.theta2) : null;
    const names = s.targets.map((_, i) => st.targetName(i + 1));
    return { scene: { targets: s.targets, selected: null, names, curves, pose }, view: v };
  };

  return (
    <div className="syn-path" data-testid="path-mode">
      <p className="note syn-intro">{st.pathIntro}</p>
      <div className="syn-stage card">
        <TargetCanvas
          targets={s.targets}
          selected={selected}
          curves={curves}
          moving={moving}
          bounds={bounds}
          view={view}
          onViewChange={setView}
          onSelect={setSelected}
          onMove={(i, p) => dispatch({ type: 'setTargets', targets: s.targets.map((q, k) => (k === i ? p : q)) })}
          onAdd={(p) => {
            dispatch({ type: 'setTargets', targets: [...s.targets, p] });
            setSelected(s.targets.length);
          }}
          onRemove={(i) => {
            dispatch({ type: 'removeTarget', index: i });
            setSelected(null);
          }}
          canvasRef={canvasRef}
          st={st}
        />
      </div>
      <div className="syn-side">
        <TargetsCard s={s} selected={selected} onSelect={setSelected} onReplace={replace} dispatch={dispatch} st={st} />
        <TaskSettings s={s} dispatch={dispatch} onFieldError={onFieldError} st={st} />
        <RunControls
          run={run}
          canRun={s.targets.length > 0}
          hold={hold}
          summary={summary}
          onRun={() => {
            // The candidate chosen stays (a task edit chose the best): a link's or a file's cd shows again.
            setShown(0);
            void run.run(task, s.seed);
          }}
          onCancel={run.cancel}
          st={st}
        />
        <CandidateList
          solutions={solutions}
          cognateOf={cognateOf}
          facts={facts}
          targets={run.task?.targets ?? s.targets}
          chosen={chosen}
          stale={stale}
          dispatch={(a) => {
            setShown(0);
            dispatch(a);
            // On a phone the canvas is above the list: bring the chosen design into view (a no-op when it shows).
            canvasRef.current?.scrollIntoView({ block: 'nearest', behavior: 'smooth' });
          }}
          st={st}
          t={t}
        />
        {choice ? (
          <ChosenDesign
            choices={choices}
            shown={Math.min(shown, choices.length - 1)}
            onShow={setShown}
            stale={stale}
            onOpen={() => onOpen({ design: choice.design, markers: s.targets, theta2: choice.theta2 })}
            onExportCsv={() => exportResultsCsv(solutions)}
            onExportSvg={() => {
              const e = exportScene();
              if (e) exportPathSvg(e.scene, e.view);
            }}
            onExportPng={() => {
              const e = exportScene();
              if (e) void exportPathPng(e.scene, e.view);
            }}
            st={st}
            t={t}
          />
        ) : null}
      </div>
    </div>
  );
}
