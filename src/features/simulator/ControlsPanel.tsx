import './ControlsPanel.css';
import { memo, useState } from 'react';
import type { Dispatch } from 'react';
import type { Linkage } from '../../solver/types';
import type { Action, AppState, Direction } from '../../shared/state/appState';
import { SAMPLE_CHOICES, SPEED_MAX, SPEED_MIN, SPEED_STEP } from '../../shared/state/appState';
import { THETA2_DECIMALS } from '../../shared/format';
import type { PresetId } from '../../shared/state/presets';
import { PRESETS, getPreset, matchPreset } from '../../shared/state/presets';
import { lengthSliderRange, needsNewRange } from './sliderRange';
import type { LockableParam } from '../../shared/url/url';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { Icon } from '../../shared/ui/Icon';
import { MotionControls } from './MotionControls';
import { NumberControl } from '../../shared/ui/NumberControl';
import { Segmented } from '../../shared/ui/Segmented';
import { FlagToggles } from '../../shared/ui/Toggle';

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
}

const LENGTH_FIELDS: readonly (keyof Linkage)[] = ['r1', 'r2', 'r3', 'r4'];

function ControlsPanelImpl({ state, dispatch, locked = [], compact = false, rocking, onStep }: ControlsPanelProps) {
  const t = useMessages();
  const l = state.linkage;
  const values = [l.r1, l.r2, l.r3, l.r4];
  const [range, setRange] = useState(() => lengthSliderRange(Math.max(...values)));
  // Re-range only when a value left the sliders' range (typed, preset, URL), never while dragging. Adjusted
  // while rendering, not in an effect: an effect's update would outlive each input of a burst (React #185).
  const wanted = needsNewRange(range, values) ? lengthSliderRange(Math.max(...values)) : range;
  if (wanted.min !== range.min || wanted.max !== range.max || wanted.step !== range.step) setRange(wanted);
  const isLocked = (p: LockableParam) => locked.includes(p);
  const presetId = matchPreset(l, state.branch, state.coupler);
  const lengthsLocked = LENGTH_FIELDS.some((f) => isLocked(f));

  return (
    <div className="controls">
      {!compact ? (
        <section className="panel-section" aria-labelledby="sec-preset">
          <h2 id="sec-preset" className="section-title">
            {t.preset}
          </h2>
          <select
            className="select"
            aria-label={t.preset}
            value={presetId ?? ''}
            disabled={lengthsLocked}
            onChange={(e) => {
              if (!e.target.value) return;
              const p = getPreset(e.target.value as PresetId);
              dispatch({
                type: 'applyPreset',
                linkage: p.linkage,
                theta2Deg: p.theta2Deg,
                branch: p.branch,
                coupler: p.coupler,
              });
            }}
          >
            <option value="">{t.presetPlaceholder}</option>
            {PRESETS.map((p) => (
              <option key={p.id} value={p.id}>
                {t.presetNames[p.id]}
              </option>
            ))}
          </select>
        </section>
      ) : null}

      <section className="panel-section" aria-labelledby="sec-links">
        <h2 id="sec-links" className="section-title">
          {t.sectionLinks}
        </h2>
        {LENGTH_FIELDS.map((f) => (
          <NumberControl
            key={f}
            field={f}
            value={l[f]}
            min={range.min}
            max={range.max}
            step={range.step}
            locked={isLocked(f)}
            onCommit={(v) => dispatch({ type: 'setLength', field: f, value: v })}
          />
        ))}
      </section>

      <section className="panel-section" aria-labelledby="sec-input">
        <h2 id="sec-input" className="section-title">
          {t.sectionInput}
        </h2>
        <NumberControl
          field="theta2"
          value={state.theta2Deg}
          decimals={THETA2_DECIMALS}
          min={0}
          max={360}
          step={0.5}
          unit="°"
          locked={isLocked('theta2')}
          onCommit={(v) => dispatch({ type: 'setTheta2', deg: v })}
        />
        <Segmented
          legend={t.branch}
          value={state.branch}
          locked={isLocked('branch')}
          options={[
            { value: 'open', label: t.branchOpen },
            { value: 'crossed', label: t.branchCrossed },
          ]}
          onChange={(b) => dispatch({ type: 'setBranch', branch: b })}
        />
      </section>

      <section className="panel-section" aria-labelledby="sec-anim">
        <h2 id="sec-anim" className="section-title">
          {t.sectionAnimation}
        </h2>
        <div className="play-row">
          <button
            type="button"
            className="icon-btn"
            aria-label={t.stepBack}
            title={t.stepBack}
            disabled={isLocked('theta2')}
            onClick={() => onStep(-1)}
          >
            <Icon name="stepBack" />
          </button>
          <button
            type="button"
            className={`btn btn-primary play-btn${isLocked('play') ? ' is-locked' : ''}`}
            disabled={isLocked('play')}
            title={isLocked('play') ? t.locked : undefined}
            onClick={() => dispatch({ type: 'setPlaying', playing: !state.playing })}
          >
            <Icon name={state.playing ? 'pause' : 'play'} size={14} />
            <span>{state.playing ? t.pause : t.play}</span>
          </button>
          <button
            type="button"
            className="icon-btn"
            aria-label={t.stepForward}
            title={t.stepForward}
            disabled={isLocked('theta2')}
            onClick={() => onStep(1)}
          >
            <Icon name="stepForward" />
          </button>
        </div>
        {!compact ? (
          <>
            <NumberControl
              field="speed"
              value={state.speedDegPerFrame}
              min={SPEED_MIN}
              max={SPEED_MAX}
              step={SPEED_STEP}
              onCommit={(v) => dispatch({ type: 'setSpeed', degPerFrame: v })}
            />
            <Segmented<'1' | '-1'>
              legend={t.direction}
              value={String(state.direction) as '1' | '-1'}
              options={[
                { value: '1', label: t.ccw },
                { value: '-1', label: t.cw },
              ]}
              onChange={(d) => dispatch({ type: 'setDirection', direction: Number(d) as Direction })}
            />
          </>
        ) : null}
        {rocking ? <p className="note">{t.rockingNote}</p> : null}
      </section>

      {!compact ? <MotionControls state={state} dispatch={dispatch} /> : null}

      {!compact ? (
        <section className="panel-section" aria-labelledby="sec-coupler">
          <h2 id="sec-coupler" className="section-title">
            {t.sectionCoupler}
          </h2>
          <NumberControl
            field="couplerDistance"
            value={state.coupler.distance}
            min={0}
            max={range.max}
            step={range.step}
            locked={isLocked('coupler')}
            onCommit={(v) => dispatch({ type: 'setCoupler', coupler: { distance: v } })}
          />
          <NumberControl
            field="couplerAngle"
            value={state.coupler.angleDeg}
            min={-180}
            max={180}
            step={1}
            unit="°"
            locked={isLocked('coupler')}
            onCommit={(v) => dispatch({ type: 'setCoupler', coupler: { angleDeg: v } })}
          />
        </section>
      ) : null}

      {!compact ? (
        <section className="panel-section" aria-labelledby="sec-display">
          <h2 id="sec-display" className="section-title">
            {t.sectionDisplay}
          </h2>
          <FlagToggles
            flags={['showGrid', 'showAngles', 'showGhost', 'showTrace', 'showDeadCentres', 'showInstantCentres']}
            state={state}
            dispatch={dispatch}
          />
          <label className="inline-field">
            <span>{t.samples}</span>
            <select
              className="select select-small"
              value={String(state.samples)}
              onChange={(e) => dispatch({ type: 'setSamples', samples: Number(e.target.value) })}
            >
              {(SAMPLE_CHOICES.includes(state.samples)
                ? SAMPLE_CHOICES
                : [...SAMPLE_CHOICES, state.samples].sort((a, b) => a - b)
              ).map((n) => (
                <option key={n} value={n}>
                  {n + 1}
                </option>
              ))}
            </select>
          </label>
        </section>
      ) : null}
    </div>
  );
}

/** The controls sidebar: preset, link lengths, input angle, branch, animation, coupler point and display toggles. */
export const ControlsPanel = memo(ControlsPanelImpl);
