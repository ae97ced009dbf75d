import { radToDeg } from '../../../solver';
import { COORD_MAX, MAX_TIME_RATIO } from '../../../shared/state/slices/synMotionSlice';
import { formatDeg, formatNumber } from '../../../shared/format';
import { NumberField } from '../../../shared/ui/NumberField';
import type { MotionMessages } from './motionMessages';
import type { TwoPoseOutcome } from './motionSolve';
import { ChoiceList } from './ChoiceList';

/** Props of RockerPanel: the two-pose outcome, the settings, and what changing them does. */
export interface RockerPanelProps {
  outcome: TwoPoseOutcome;
  swingDeg: number;
  auto: boolean;
  timeRatio: number;
  choice: number;
  onGround: (length: number | null) => void;
  onTimeRatio: (ratio: number) => void;
  onChoose: (index: number) => void;
  mt: MotionMessages;
}

/** Two poses: the pole (rocker pivot), the ground length (auto: twice the rocker) and Q, and the crank pivots found. */
export function RockerPanel({
  outcome,
  swingDeg,
  auto,
  timeRatio,
  choice,
  onGround,
  onTimeRatio,
  onChoose,
  mt,
}: RockerPanelProps) {
  const f = (v: number) => formatNumber(v, 5);
  return (
    <div className="synmode-rocker">
      {outcome.pole ? (
        <p className="note" data-testid="motion-pole">
          {mt.poleNote(f(outcome.pole.x), f(outcome.pole.y), f(outcome.rocker), formatDeg(swingDeg, 1))}
        </p>
      ) : null}
      <div className="synmode-field-row">
        <NumberField
          live
          label={mt.groundLength}
          value={outcome.ground}
          decimals={6}
          check={(v) => (v > 0 && v <= COORD_MAX ? null : mt.mustBePositive)}
          errorText={(text, kept, why) => mt.cellError(mt.groundLength, text, kept, why)}
          onCommit={onGround}
        />
        <button type="button" className="btn btn-small" disabled={auto} onClick={() => onGround(null)}>
          {mt.groundAuto(f(2 * outcome.rocker))}
        </button>
      </div>
      <NumberField
        live
        label={mt.timeRatio}
        value={timeRatio}
        decimals={6}
        check={(v) => (v >= 1 && v <= MAX_TIME_RATIO ? null : mt.mustBeBetween('1', String(MAX_TIME_RATIO)))}
        errorText={(text, kept, why) => mt.cellError(mt.timeRatio, text, kept, why)}
        onCommit={onTimeRatio}
      />
      {outcome.results.length > 1 ? (
        <ChoiceList
          legend={mt.rockersTitle}
          items={outcome.results.map((r, i) => ({
            label: mt.rockerItem(i + 1, formatDeg(radToDeg(r.transmission.min), 1)),
            detail: '',
          }))}
          chosen={Math.min(choice, outcome.results.length - 1)}
          onChoose={onChoose}
        />
      ) : null}
    </div>
  );
}
