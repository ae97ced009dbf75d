import { useId } from 'react';
import { formatNumber } from '../../../shared/format';
import type { FunctionMessages } from './functionMessages';
import type { useSweep } from './useSweep';

/** Props of FunctionSweep: the sweep (useSweep's), x's range, f(x) wanted and generated at the sweep's x, and texts. */
export interface FunctionSweepProps {
  sweep: ReturnType<typeof useSweep>;
  xRange: readonly [number, number];
  want: number;
  got: number;
  fm: FunctionMessages;
}

/** Play/Pause, the x slider and the readout of f(x) wanted against generated, under the Function canvas. */
export function FunctionSweep({ sweep, xRange, want, got, fm }: FunctionSweepProps) {
  const sliderId = useId();
  const fmt = (v: number) => formatNumber(v, 5);
  return (
    <div className="synmode-sweep">
      <button type="button" className="btn btn-small" onClick={() => sweep.setPlaying(!sweep.playing)}>
        {sweep.playing ? fm.pause : fm.play}
      </button>
      <label htmlFor={sliderId}>{fm.xSlider}</label>
      <input
        id={sliderId}
        type="range"
        min={Math.min(...xRange)}
        max={Math.max(...xRange)}
        step={Math.abs(xRange[1] - xRange[0]) / 200}
        value={sweep.x}
        onChange={(e) => sweep.setX(Number(e.target.value))}
      />
      <span className="synmode-readout">{fm.readout(fmt(sweep.x), fmt(want), fmt(got))}</span>
    </div>
  );
}
