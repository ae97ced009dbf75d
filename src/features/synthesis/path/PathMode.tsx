import { useMemo, useState } from 'react';
import { useMessages } from '../../../shared/i18n/MessagesContext';
import type { SynthesisModeProps } from '../openDesign';
import { synthesisMessagesFor } from '../synthesisMessages';
import { CandidateList } from './CandidateList';
import { ChosenDesign } from './ChosenDesign';
import { SynthesisPrint } from '../print/SynthesisPrint';
import { exportResultsCsv } from './pathExports';
import { pathPrintContent } from './pathPrint';
import { pathTaskOf, samePathTask } from './pathTaskOf';
import { RunControls } from './RunControls';
import { holdText, noFitSummary } from './runNotes';
import { TargetCanvas } from './TargetCanvas';
import { TargetsCard } from './TargetsCard';
import { TaskSettings } from './TaskSettings';
import { useFieldErrors } from './useFieldErrors';
import { usePathChoices } from './usePathChoices';
import { usePathPicture } from './usePathPicture';
import type { SynthesisPool } from './usePathSynthesis';
import { usePathSynthesis } from './usePathSynthesis';
import { useTargetEditing } from './useTargetEditing';

/** Props of PathMode: a mode's props and how to make the pool of solver workers. */
export interface PathModeProps extends SynthesisModeProps {
  createPool: () => SynthesisPool;
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
  const edit = useTargetEditing(s.targets, dispatch, st);
  const [fieldErrors, onFieldError] = useFieldErrors();
  const run = usePathSynthesis(createPool);
  const [shown, setShown] = useState(0);
  const chosen = Math.min(s.chosen, Math.max(0, (run.solutions?.length ?? 0) - 1));
  const { choices, solutions, facts, cognateOf } = usePathChoices(run, chosen);
  const shownAt = Math.min(shown, choices.length - 1);
  const choice = choices[shownAt] ?? null;
  const task = useMemo(() => pathTaskOf(s), [s]);
  // The answers belong to the task they were computed for: after an edit they are drawn faint and not opened.
  const stale = run.task !== null && !samePathTask(run.task, task);
  const summary = useMemo(() => noFitSummary(run, stale, st), [run, stale, st]);
  const fitKey = `${edit.replaced}|${run.elapsedMs}|${chosen}|${shown}`;
  const { curves, moving, bounds } = usePathPicture(s.targets, choices, shown, stale, fitKey);

  return (
    <div className="syn-path" data-testid="path-mode">
      <p className="note syn-intro">{st.pathIntro}</p>
      <div className="syn-stage card">
        <TargetCanvas
          targets={s.targets}
          selected={edit.selected}
          curves={curves}
          moving={moving}
          bounds={bounds}
          view={edit.view}
          onViewChange={edit.setView}
          onSelect={edit.setSelected}
          onMove={edit.onMove}
          onAdd={edit.onAdd}
          onRemove={edit.onRemove}
          canvasRef={edit.canvasRef}
          st={st}
        />
      </div>
      <div className="syn-side">
        <TargetsCard
          s={s}
          selected={edit.selected}
          onSelect={edit.setSelected}
          onReplace={edit.replace}
          dispatch={dispatch}
          st={st}
        />
        <TaskSettings s={s} dispatch={dispatch} onFieldError={onFieldError} st={st} />
        <RunControls
          run={run}
          canRun={s.targets.length > 0}
          hold={holdText(fieldErrors, s, st)}
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
            edit.canvasRef.current?.scrollIntoView({ block: 'nearest', behavior: 'smooth' });
          }}
          st={st}
          t={t}
        />
        {choice ? (
          <ChosenDesign
            choices={choices}
            shown={shownAt}
            onShow={setShown}
            stale={stale}
            onOpen={() => onOpen({ design: choice.design, markers: s.targets, theta2: choice.theta2 })}
            onExportCsv={() => exportResultsCsv(solutions)}
            {...edit.sceneExports(bounds, curves, choice)}
            st={st}
            t={t}
          />
        ) : null}
      </div>
      <SynthesisPrint
        m={st.print}
        build={() =>
          pathPrintContent({
            s,
            unit: state.design.lengthUnit,
            solution: solutions?.[chosen] ?? null,
            rank: chosen,
            choices,
            shown: shownAt,
            stale,
            st,
            t,
          })
        }
      />
    </div>
  );
}
