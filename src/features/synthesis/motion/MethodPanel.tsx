import type { Dispatch } from 'react';
import type { Action, AppState } from '../../../shared/state/appState';
import { useMessages } from '../../../shared/i18n/MessagesContext';
import { formatNumber } from '../../../shared/format';
import type { MotionMessages } from './motionMessages';
import type { MotionOutcome } from './motionSolve';
import { pivotsFor } from './motionEdits';
import { PivotPanel } from './PivotPanel';
import { DyadPanel } from './DyadPanel';
import { RockerPanel } from './RockerPanel';
import { ChoiceList } from './ChoiceList';

/** Props of MethodPanel: the outcome, the state and dispatch, the curve slider's place, and the texts. */
export interface MethodPanelProps {
  outcome: MotionOutcome;
  state: AppState;
  dispatch: Dispatch<Action>;
  cursor: number;
  setCursor: (index: number) => void;
  mt: MotionMessages;
}

/**
 * The method's own controls for the number of poses: the rocker's ground and Q (two), the pivots (three), the dyad
 * picker (four), the Burmester points' four-bars (five), the least-squares dyads' four-bars (six to twenty).
 */
export function MethodPanel({ outcome, state, dispatch, cursor, setCursor, mt }: MethodPanelProps) {
  const s = state.synMotion;
  const t = useMessages();
  switch (outcome.count) {
    case 2:
      return (
        <RockerPanel
          outcome={outcome}
          swingDeg={s.poses[1].angleDeg - s.poses[0].angleDeg}
          auto={s.groundLength === null}
          timeRatio={s.timeRatio}
          choice={s.choice}
          onGround={(length) => dispatch({ type: 'setSynGround', length })}
          onTimeRatio={(ratio) => dispatch({ type: 'setSynTimeRatio', ratio })}
          onChoose={(choice) => dispatch({ type: 'setSynChoice', choice })}
          mt={mt}
        />
      );
    case 3:
      return (
        <PivotPanel
          choice={s.pivotChoice}
          pivots={s.pivots}
          onChoice={(choice) =>
            dispatch({
              type: 'setSynPivotChoice',
              choice,
              pivots: pivotsFor(choice, outcome.chosen, s.poses, s.pivots),
            })
          }
          onPivot={(index, point) => dispatch({ type: 'setSynPivot', index, point })}
          mt={mt}
        />
      );
    case 4:
      return (
        <DyadPanel
          samples={outcome.curves.flat()}
          cursor={cursor}
          onCursor={setCursor}
          onPick={(pair) => dispatch({ type: 'pickSynDyad', center: pair.center })}
          onClear={() => dispatch({ type: 'clearSynDyads' })}
          picked={s.dyadPicks.length}
          mt={mt}
        />
      );
    case 6:
      return (
        <>
          <p className="note" data-testid="approx-count">
            {mt.approxDyads(outcome.dyads.length)}
          </p>
          {outcome.fourBars.length ? (
            <ChoiceList
              legend={mt.approxFourBarsTitle}
              testId="approx-fourbars"
              items={outcome.fourBars.map((b, i) => ({
                label: mt.approxItem(
                  i + 1,
                  b.pairs ? `${b.pairs[0] + 1} + ${b.pairs[1] + 1}` : '',
                  formatNumber(b.rms ?? NaN, 3),
                ),
                detail: `${t.types[b.type]} · ${b.defects.length ? b.defects.map((d) => mt.defectShort[d]).join(', ') : mt.noDefectsShort}`,
              }))}
              chosen={Math.min(s.choice, outcome.fourBars.length - 1)}
              onChoose={(choice) => dispatch({ type: 'setSynChoice', choice })}
            />
          ) : null}
        </>
      );
    default:
      return (
        <>
          <p className="note" data-testid="burmester-count">
            {mt.burmesterPoints(outcome.points.length)}
          </p>
          {outcome.fourBars.length ? (
            <ChoiceList
              legend={mt.fourBarsTitle}
              testId="burmester-fourbars"
              items={outcome.fourBars.map((b, i) => ({
                label: mt.fourBarItem(i + 1, b.pairs ? `${b.pairs[0] + 1} + ${b.pairs[1] + 1}` : ''),
                detail: `${t.types[b.type]} · ${b.defects.length ? b.defects.map((d) => mt.defectShort[d]).join(', ') : mt.noDefectsShort}`,
              }))}
              chosen={Math.min(s.choice, outcome.fourBars.length - 1)}
              onChoose={(choice) => dispatch({ type: 'setSynChoice', choice })}
            />
          ) : null}
        </>
      );
  }
}
