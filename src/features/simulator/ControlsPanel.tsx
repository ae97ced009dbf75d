import './ControlsPanel.css';
import { memo, useState } from 'react';
import type { Dispatch } from 'react';
import type { Action, AppState } from '../../shared/state/appState';
import { matchPreset } from '../../shared/state/presets';
import { lengthSliderRange, needsNewRange } from './sliderRange';
import type { SliderRange } from './sliderRange';
import type { LockableParam } from '../../shared/url/url';
import { MotionControls } from './MotionControls';
import {
  AnimationSection,
  CouplerSection,
  DisplaySection,
  InputSection,
  LENGTH_FIELDS,
  LinksSection,
  PresetSection,
} from './ControlsSections';

/** Props of ControlsPanel: the state, its dispatcher, locked parameters and what the layout shows. */
export interface ControlsPanelProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  locked?: readonly LockableParam[];
  /** Embed layout: lengths, angle, branch and play only. */
  compact?: boolean;
  /** The input cannot turn fully: explain that the animation rocks. */
  rocking: boolean;
  onStep: (sign: 1 | -1) => void;
  /** Phone layout: θ2, the branch, Play and step are in the phone bar, so the panel leaves them out. */
  phone?: boolean;
}

/** The range the length sliders share, re-chosen only when a value leaves it. */
function useLengthRange(values: readonly number[]): SliderRange {
  const [range, setRange] = useState(() => lengthSliderRange(Math.max(...values)));
  // Re-range only when a value left the sliders' range (typed, preset, URL), never while dragging. Adjusted
  // while rendering, not in an effect: an effect's update would outlive each input of a burst (React #185).
  const wanted = needsNewRange(range, values) ? lengthSliderRange(Math.max(...values)) : range;
  if (wanted.min !== range.min || wanted.max !== range.max || wanted.step !== range.step) setRange(wanted);
  return range;
}

function ControlsPanelImpl({
  state,
  dispatch,
  locked = [],
  compact = false,
  rocking,
  onStep,
  phone = false,
}: ControlsPanelProps) {
  const l = state.design.linkage;
  const range = useLengthRange([l.r1, l.r2, l.r3, l.r4]);
  const isLocked = (p: LockableParam) => locked.includes(p);
  const section = { state, dispatch, isLocked };
  return (
    <div className="controls">
      {!compact ? (
        <PresetSection
          presetId={matchPreset(l, state.design.branch, state.design.coupler)}
          disabled={LENGTH_FIELDS.some((f) => isLocked(f))}
          dispatch={dispatch}
        />
      ) : null}
      <LinksSection {...section} range={range} />
      {phone ? null : <InputSection {...section} />}
      <AnimationSection {...section} onStep={onStep} compact={compact} rocking={rocking} withoutPlay={phone} />
      {!compact ? <MotionControls state={state} dispatch={dispatch} /> : null}
      {!compact ? <CouplerSection {...section} range={range} /> : null}
      {!compact ? <DisplaySection state={state} dispatch={dispatch} /> : null}
    </div>
  );
}

/** The controls sidebar: preset, link lengths, input angle, branch, animation, coupler point and display toggles. */
export const ControlsPanel = memo(ControlsPanelImpl);
