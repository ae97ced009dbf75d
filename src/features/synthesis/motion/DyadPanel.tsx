import { useId } from 'react';
import type { BurmesterPair } from '../../../synthesis';
import { formatNumber } from '../../../shared/format';
import type { MotionMessages } from './motionMessages';

/** Props of DyadPanel: the curve's samples, the slider's place on them, the dyads picked, and the actions. */
export interface DyadPanelProps {
  samples: readonly BurmesterPair[];
  cursor: number;
  onCursor: (index: number) => void;
  onPick: (pair: BurmesterPair) => void;
  onClear: () => void;
  picked: number;
  mt: MotionMessages;
}

/**
 * Four poses: the dyads picked so far, and the keyboard's way to pick one: a slider along the centre-point curve
 * (its samples, every branch in turn) and a button that picks the dyad it is on.
 */
export function DyadPanel({ samples, cursor, onCursor, onPick, onClear, picked, mt }: DyadPanelProps) {
  const id = useId();
  const at = samples[Math.min(cursor, samples.length - 1)];
  return (
    <div className="synmode-dyads">
      <p className="note">{mt.pickHint}</p>
      <p data-testid="dyads-picked">{mt.picked(picked)}</p>
      {samples.length ? (
        <div className="synmode-curve-slider">
          <label htmlFor={id}>{mt.curvePoint}</label>
          <input
            id={id}
            type="range"
            min={0}
            max={samples.length - 1}
            step={1}
            value={Math.min(cursor, samples.length - 1)}
            aria-valuetext={at ? `(${formatNumber(at.center.x, 4)}, ${formatNumber(at.center.y, 4)})` : undefined}
            onChange={(e) => onCursor(Number(e.target.value))}
          />
          <div className="export-buttons">
            <button type="button" className="btn btn-small" disabled={!at} onClick={() => at && onPick(at)}>
              {mt.pickThis}
            </button>
            <button type="button" className="btn btn-small" disabled={picked === 0} onClick={onClear}>
              {mt.clearPicks}
            </button>
          </div>
        </div>
      ) : null}
    </div>
  );
}
