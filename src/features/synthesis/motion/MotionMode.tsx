import './synthesisModes.css';
import { useMemo, useState } from 'react';
import type { Dispatch } from 'react';
import type { Point } from '../../../solver';
import { toFrame } from '../../../synthesis';
import type { Action, AppState } from '../../../shared/state/appState';
import type { PoseDeg } from '../../../shared/state/slices/synMotionSlice';
import { useMessages } from '../../../shared/i18n/MessagesContext';
import { Segmented } from '../../../shared/ui/Segmented';
import { formatNumber } from '../../../shared/format';
import type { OpenDesign } from '../openDesign';
import { motionMessagesFor } from './motionMessages';
import { solveMotion, toPose } from './motionSolve';
import type { MotionPicture } from './motionPicture';
import { centroid, nearestSample } from './motionPicture';
import { nextPose } from './motionEdits';
import { problemText } from './motionText';
import { MotionCanvas } from './MotionCanvas';
import { PoseTable } from './PoseTable';
import { MethodPanel } from './MethodPanel';
import { MotionFacts } from './MotionFacts';

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
  const s = state.synMotion;
  const outcome = useMemo(() => solveMotion(s), [s]);
  const [selectedRaw, setSelected] = useState(0);
  const [shownRaw, setShown] = useState(0);
  // The curve slider's sample; until it is moved, the one nearest the poses (so its mark is in view).
  const [cursorRaw, setCursor] = useState<number | null>(null);
  const selected = Math.min(selectedRaw, s.poses.length - 1);
  const chosen = outcome.chosen;
  const shownPose = Math.min(shownRaw, (chosen?.theta2.length ?? 1) - 1);
  const poses = useMemo(() => s.poses.map(toPose), [s.poses]);
  const samples = useMemo(() => (outcome.count === 4 ? outcome.curves.flat() : []), [outcome]);
  const cursor = Math.min(cursorRaw ?? nearestSample(samples, centroid(poses)), Math.max(0, samples.length - 1));
  const picture: MotionPicture = {
    poses,
    selected,
    outcome,
    pivotChoice: s.pivotChoice,
    pivots: s.pivots,
    shownPose,
    cursor: samples[cursor] ?? null,
    legend: { centre: mt.centreCurve, circle: mt.circleCurve },
  };
  const sel = s.poses[selected];
  const setPose = (index: number, pose: PoseDeg) => dispatch({ type: 'setSynPose', index, pose });
  const onPivot = (index: 0 | 1, at: Point) =>
    dispatch({ type: 'setSynPivot', index, point: s.pivotChoice === 'moving' ? toFrame(poses[0], at) : at });
  const onTap = (at: Point, reach: number) => {
    if (outcome.count !== 4) return;
    let best: Point | null = null;
    let bestD = reach;
    for (const d of samples) {
      const dist = Math.hypot(d.center.x - at.x, d.center.y - at.y);
      if (dist <= bestD) {
        bestD = dist;
        best = d.center;
      }
    }
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
          cursor={cursor}
          setCursor={setCursor}
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
          <div className="synmode-design" data-testid="motion-design">
            <h3 className="section-title">{mt.designTitle}</h3>
            <MotionFacts candidate={chosen} mt={mt} t={t} />
            <Segmented
              legend={mt.shownAt}
              value={String(shownPose)}
              options={chosen.theta2.map((_, i) => ({ value: String(i), label: mt.poseName(i + 1) }))}
              onChange={(v) => setShown(Number(v))}
            />
            <button
              type="button"
              className="btn btn-primary"
              onClick={() =>
                onOpen({
                  design: chosen.design,
                  markers: s.poses.map((p) => ({ x: p.x, y: p.y })),
                  theta2: chosen.theta2[shownPose],
                })
              }
            >
              {mt.openInSimulator}
            </button>
          </div>
        ) : null}
      </section>
    </div>
  );
}
