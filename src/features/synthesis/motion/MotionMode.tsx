import './synthesisModes.css';
import { useMemo } from 'react';
import type { Dispatch } from 'react';
import type { Point } from '../../../solver';
import { toFrame } from '../../../synthesis';
import type { Action, AppState } from '../../../shared/state/appState';
import type { PoseDeg } from '../../../shared/state/slices/synMotionSlice';
import { useMessages } from '../../../shared/i18n/MessagesContext';
import { formatNumber } from '../../../shared/format';
import type { OpenDesign } from '../openDesign';
import { motionMessagesFor } from './motionMessages';
import { solveMotion } from './motionSolve';
import { dyadCentreNear, useMotionView } from './useMotionView';
import { nextPose } from './motionEdits';
import { problemText } from './motionText';
import { MotionCanvas } from './MotionCanvas';
import { PoseTable } from './PoseTable';
import { MethodPanel } from './MethodPanel';
import { MotionDesignCard } from './MotionDesignCard';
import { SynthesisPrint } from '../print/SynthesisPrint';
import { synthesisMessagesFor } from '../synthesisMessages';
import { motionPrintContent } from './motionPrint';

/** Props of MotionMode (as the synthesis page renders every mode). */
export interface MotionModeProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  /** "Open in simulator" with the chosen design and the poses' points as markers. */
  onOpen: (design: OpenDesign) => void;
}

/**
 * Motion generation (運動生成): 2 to 5 poses placed on a pan-and-zoom canvas or typed in a table; the synthesis
 * module's method for their count (two-position rocker, three positions with their construction, the Burmester
 * curves with dyads picked on them, the Burmester points and their four-bars); every result screened for order,
 * branch and Grashof defects, said in words; Open in simulator.
 */
export function MotionMode({ state, dispatch, onOpen }: MotionModeProps) {
  const t = useMessages();
  const mt = motionMessagesFor(state.shell.locale);
  const st = synthesisMessagesFor(state.shell.locale);
  const s = state.synMotion;
  const outcome = useMemo(() => solveMotion(s), [s]);
  const view = useMotionView(s, outcome, mt);
  const { picture, poses, selected, setSelected, shownPose } = view;
  const chosen = outcome.chosen;
  const sel = s.poses[selected];
  const setPose = (index: number, pose: PoseDeg) => dispatch({ type: 'setSynPose', index, pose });
  const onPivot = (index: 0 | 1, at: Point) =>
    dispatch({ type: 'setSynPivot', index, point: s.pivotChoice === 'moving' ? toFrame(poses[0], at) : at });
  const onTap = (at: Point, reach: number) => {
    if (outcome.count !== 4) return;
    const best = dyadCentreNear(view.samples, at, reach);
    if (best) dispatch({ type: 'pickSynDyad', center: best });
  };
  const f = (v: number) => formatNumber(v, 4);

  return (
    <div className="synmode-mode synmode-motion" data-testid="motion-mode" data-count={s.poses.length}>
      <section className="card synmode-canvas-card" aria-label={mt.canvasLabel}>
        <MotionCanvas
          picture={picture}
          onPose={setPose}
          onPivot={onPivot}
          onSelect={setSelected}
          onTap={onTap}
          labels={{
            canvas: mt.canvasLabel,
            hint: mt.canvasHint,
            selected: sel ? mt.selectedPose(selected + 1, f(sel.x), f(sel.y), f(sel.angleDeg)) : '',
            zoomIn: mt.zoomIn,
            zoomOut: mt.zoomOut,
            resetView: mt.resetView,
          }}
        />
      </section>
      <section className="card synmode-side" aria-labelledby="synmode-motion-poses">
        <p className="note">{mt.intro}</p>
        <h3 id="synmode-motion-poses" className="section-title">
          {mt.posesTitle}
        </h3>
        <PoseTable
          poses={s.poses}
          selected={selected}
          onSelect={setSelected}
          onPose={setPose}
          onAdd={() => {
            const next = nextPose(s.poses);
            if (next) dispatch({ type: 'setSynPoses', poses: [...s.poses, next] });
          }}
          onRemove={(index) => dispatch({ type: 'setSynPoses', poses: s.poses.filter((_, i) => i !== index) })}
          mt={mt}
        />
        <p className="synmode-method" data-testid="motion-method">
          {mt.methodFor[outcome.count]}
        </p>
        <MethodPanel
          outcome={outcome}
          state={state}
          dispatch={dispatch}
          cursor={view.cursor}
          setCursor={view.setCursor}
          mt={mt}
        />
        {outcome.problem && !chosen ? (
          <p
            className={outcome.problem.code === 'pickTwo' ? 'note' : 'note note-error'}
            role="status"
            data-testid="motion-problem"
          >
            {problemText(mt, outcome.problem)}
          </p>
        ) : null}
        {chosen ? (
          <MotionDesignCard
            chosen={chosen}
            shownPose={shownPose}
            onShow={view.setShown}
            onOpen={() =>
              onOpen({
                design: chosen.design,
                markers: s.poses.map((p) => ({ x: p.x, y: p.y })),
                theta2: chosen.theta2[shownPose],
              })
            }
            mt={mt}
            t={t}
          />
        ) : null}
      </section>
      <SynthesisPrint
        m={st.print}
        build={() => motionPrintContent({ s, outcome, picture, unit: state.design.lengthUnit, st, mt, t })}
      />
    </div>
  );
}
