import { useSyncExternalStore } from 'react';
import type { Dispatch } from 'react';
import type { Action, SpatialState } from '../../shared/state/appState';
import type { SpatialField } from '../../shared/state/slices/spatialSlice';
import { Segmented } from '../../shared/ui/Segmented';
import type { SpatialPreset } from '../../spatial';
import type { SliderRange } from './SpatialFieldControl';
import { SpatialFieldControl } from './SpatialFieldControl';
import type { SpatialMessages } from './spatialMessages';
import type { SpatialPlayhead } from './spatialPlayhead';
import { PRESET_IDS, presetById, presetOf, presetPatch } from './spatialModel';

/** Props of SpatialControls: the state, dispatch, Play and the step, and the strings. */
export interface SpatialControlsProps {
  s: SpatialState;
  dispatch: Dispatch<Action>;
  playing: boolean;
  onPlay: (playing: boolean) => void;
  onStep: (deltaDeg: number) => void;
  sm: SpatialMessages;
  /** Play's frame ahead of the state: the θ2 field follows it. */
  playhead: SpatialPlayhead;
  /** What an embed locks (lock=params,theta2,branch,play); default nothing. */
  locked?: SpatialLocks;
}

/**
 * The spatial page's embed locks: the linkage's parameters (kind, preset, values, the input's ω2 and α2), θ2 (and
 * Step), branch, Play.
 */
export interface SpatialLocks {
  params: boolean;
  theta2: boolean;
  branch: boolean;
  play: boolean;
}

const UNLOCKED: SpatialLocks = { params: false, theta2: false, branch: false, play: false };

const ARC: SliderRange = { min: 0.5, max: 179.5, step: 0.5 };
const TURN: SliderRange = { min: -180, max: 180, step: 1 };
const LENGTH: SliderRange = { min: 0.1, max: 10, step: 0.1 };

/** Each kind's fields and their sliders, in the panel's order. */
const FIELDS: Record<SpatialState['kind'], [SpatialField, SliderRange][]> = {
  sph: [
    ['a1Deg', ARC],
    ['a2Deg', ARC],
    ['a3Deg', ARC],
    ['a4Deg', ARC],
    ['pDistDeg', { min: 0, max: 179, step: 0.5 }],
    ['pAngleDeg', TURN],
  ],
  rssr: [
    ['r2', LENGTH],
    ['r3', LENGTH],
    ['r4', LENGTH],
    ['a', { min: 0, max: 10, step: 0.1 }],
    ['betaDeg', TURN],
    ['h2', { min: -5, max: 5, step: 0.1 }],
    ['h4', { min: -5, max: 5, step: 0.1 }],
  ],
};

/** The θ2 field and slider: the state's θ2, or Play's while it runs ahead (only this field re-renders per frame). */
function Theta2Field({
  stateDeg,
  playhead,
  onCommit,
  sm,
  locked,
}: {
  stateDeg: number;
  playhead: SpatialPlayhead;
  onCommit: (value: number) => void;
  sm: SpatialMessages;
  locked: boolean;
}) {
  const frame = useSyncExternalStore(playhead.subscribe, playhead.get);
  return (
    <SpatialFieldControl
      field="theta2Deg"
      value={frame?.theta2Deg ?? stateDeg}
      slider={{ min: 0, max: 359.5, step: 0.5 }}
      onCommit={onCommit}
      sm={sm}
      decimals={2}
      locked={locked}
    />
  );
}

/** The linkage's controls: kind, preset, its values, θ2 with Play and Step, and the branch. */
export function SpatialControls(props: SpatialControlsProps) {
  const { s, dispatch, playing, onPlay, onStep, sm, playhead, locked = UNLOCKED } = props;
  const set = (field: SpatialField) => (value: number) => dispatch({ type: 'setSpatialField', field, value });
  const preset = presetOf(s);
  return (
    <div className="spatial-controls">
      <Segmented
        legend={sm.kindLegend}
        value={s.kind}
        locked={locked.params}
        options={[
          { value: 'sph', label: sm.kindSpherical },
          { value: 'rssr', label: sm.kindRssr },
        ]}
        onChange={(kind) => dispatch({ type: 'setSpatial', patch: { kind } })}
      />
      <label className="spatial-preset">
        <span className="numctl-label">{sm.presetLabel}</span>
        <select
          className="select select-small"
          value={preset ?? ''}
          disabled={locked.params}
          onChange={(e) => {
            if (!e.target.value) return;
            const p = presetById(e.target.value as SpatialPreset['id']);
            dispatch({ type: 'setSpatial', patch: presetPatch(p) });
          }}
        >
          {preset === null ? <option value="">{sm.presetCustom}</option> : null}
          {PRESET_IDS.map((id) => (
            <option key={id} value={id}>
              {sm.presetNames[id]}
            </option>
          ))}
        </select>
      </label>
      <div className="spatial-fields">
        {FIELDS[s.kind].map(([field, slider]) => (
          <SpatialFieldControl
            key={`${s.kind}-${field}`}
            field={field}
            value={s[field]}
            slider={slider}
            onCommit={set(field)}
            sm={sm}
            locked={locked.params}
          />
        ))}
      </div>
      <div className="spatial-input">
        <Theta2Field
          stateDeg={s.theta2Deg}
          playhead={playhead}
          onCommit={set('theta2Deg')}
          sm={sm}
          locked={locked.theta2}
        />
        <div className="spatial-play">
          <button
            type="button"
            className="btn btn-small"
            onClick={() => onStep(-1)}
            aria-label={sm.stepBack}
            disabled={locked.theta2}
          >
            <span aria-hidden="true">◀ 1°</span>
          </button>
          <button
            type="button"
            className="btn btn-primary btn-small"
            onClick={() => onPlay(!playing)}
            disabled={locked.play || locked.theta2}
          >
            {playing ? sm.pause : sm.play}
          </button>
          <button
            type="button"
            className="btn btn-small"
            onClick={() => onStep(1)}
            aria-label={sm.stepForward}
            disabled={locked.theta2}
          >
            <span aria-hidden="true">1° ▶</span>
          </button>
        </div>
        <Segmented
          legend={sm.branchLegend}
          value={s.branch}
          locked={locked.branch}
          options={[
            { value: 'open', label: sm.branchOpen },
            { value: 'crossed', label: sm.branchCrossed },
          ]}
          onChange={(branch) => dispatch({ type: 'setSpatial', patch: { branch } })}
        />
        <div className="spatial-fields spatial-rates">
          <SpatialFieldControl
            field="omega2RadPerS"
            value={s.omega2RadPerS}
            slider={{ min: -20, max: 20, step: 0.1 }}
            onCommit={set('omega2RadPerS')}
            sm={sm}
            locked={locked.params}
          />
          <SpatialFieldControl
            field="alpha2RadPerS2"
            value={s.alpha2RadPerS2}
            slider={{ min: -50, max: 50, step: 0.5 }}
            onCommit={set('alpha2RadPerS2')}
            sm={sm}
            locked={locked.params}
          />
        </div>
      </div>
    </div>
  );
}
