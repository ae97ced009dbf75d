import { useMemo, useSyncExternalStore } from 'react';
import type { Dispatch } from 'react';
// The solver's module itself, not its barrel (the barrel pulls the sweep and NR into the main bundle).
import { inputRange } from '../../solver/classify';
import { assemblesAnywhere } from '../../shared/state/animation';
import type { Linkage } from '../../solver/types';
import type { Action, AppState, Direction } from '../../shared/state/appState';
import { SAMPLE_CHOICES, SPEED_MAX, SPEED_MIN, SPEED_STEP } from '../../shared/state/appState';
import { THETA2_DECIMALS } from '../../shared/format';
import type { PresetId } from '../../shared/state/presets';
import { PRESETS, getPreset } from '../../shared/state/presets';
import type { LockableParam } from '../../shared/url/url';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { Icon } from '../../shared/ui/Icon';
import { NumberControl } from '../../shared/ui/NumberControl';
import { PanelSection } from '../../shared/ui/PanelSection';
import { Segmented } from '../../shared/ui/Segmented';
import { SelectMenu } from '../../shared/ui/SelectMenu';
import type { LengthUnit } from '../../shared/state/slices/designSlice';
import { LENGTH_UNITS } from '../../shared/state/slices/designSlice';
import { FlagToggles } from '../../shared/ui/Toggle';
import type { SliderRange } from './sliderRange';
import { useTheta2Scrub } from './theta2Scrub';

/** The four link lengths, in the order the controls show them. */
export const LENGTH_FIELDS: readonly (keyof Linkage)[] = ['r1', 'r2', 'r3', 'r4'];

/** Props every section of the controls gets: the state, its dispatcher and which parameters are locked. */
export interface ControlsSectionProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  isLocked: (p: LockableParam) => boolean;
}

/** The preset menu (disabled while a length is locked); a preset sets the lengths, θ2, branch and coupler point. */
export function PresetSection({
  presetId,
  disabled,
  dispatch,
}: {
  presetId: PresetId | null;
  disabled: boolean;
  dispatch: Dispatch<Action>;
}) {
  const t = useMessages();
  return (
    <PanelSection id="sec-preset" title={t.preset}>
      <SelectMenu<PresetId | ''>
        className="select"
        label={t.preset}
        value={presetId ?? ''}
        disabled={disabled}
        options={[
          { value: '', label: t.presetPlaceholder },
          ...PRESETS.map((p) => ({ value: p.id, label: t.presetNames[p.id] })),
        ]}
        onChange={(id) => {
          if (!id) return;
          const p = getPreset(id);
          dispatch({
            type: 'applyPreset',
            linkage: p.linkage,
            theta2Deg: p.theta2Deg,
            branch: p.branch,
            coupler: p.coupler,
          });
        }}
      />
    </PanelSection>
  );
}

/**
 * The four link lengths, each a slider and field on the shared range, and their unit: choosing one converts the
 * lengths (the same linkage); not offered while a length is locked.
 */
export function LinksSection({ state, dispatch, isLocked, range }: ControlsSectionProps & { range: SliderRange }) {
  const t = useMessages();
  const from = state.design.lengthUnit;
  return (
    <PanelSection holdOffScreen={state.motion.playing} id="sec-links" title={t.sectionLinks}>
      {LENGTH_FIELDS.some((f) => isLocked(f)) ? null : (
        <>
          <Segmented<LengthUnit>
            legend={t.lengthUnit}
            value={from}
            options={LENGTH_UNITS.map((u) => ({ value: u, label: u }))}
            onChange={(to) => dispatch({ type: 'setLengthUnit', from, to })}
          />
          <p className="footnote">{t.lengthUnitNote}</p>
        </>
      )}
      {LENGTH_FIELDS.map((f) => (
        <NumberControl
          key={f}
          field={f}
          value={state.design.linkage[f]}
          min={range.min}
          max={range.max}
          step={range.step}
          unit={state.design.lengthUnit}
          locked={isLocked(f)}
          onCommit={(v) => dispatch({ type: 'setLength', field: f, value: v })}
        />
      ))}
    </PanelSection>
  );
}

/** θ2's slider keys: arrows 1°, Page Up/Down 10°, around the circle. */
const THETA2_KEYS = { step: 1 } as const;
/** The coupler angle's slider keys: the same steps on (−180°, 180°]. */
const COUPLER_ANGLE_KEYS = { step: 1 } as const;

const noSubscription = () => () => {};
const nothingDragged = () => null;

/**
 * The input angle θ2: slider and field over [0, 360]. A drag of the slider moves the playhead (Theta2Scrub), so the
 * canvas follows every value and the state a few times a second; slider and field show the dragged value meanwhile.
 */
export function Theta2Control({ state, dispatch, isLocked }: ControlsSectionProps) {
  const scrub = useTheta2Scrub();
  const dragged = useSyncExternalStore(scrub?.subscribe ?? noSubscription, scrub?.dragged ?? nothingDragged);
  return (
    <NumberControl
      field="theta2"
      value={dragged ?? state.motion.theta2Deg}
      drag={scrub}
      decimals={THETA2_DECIMALS}
      min={0}
      max={360}
      step={0.5}
      turn={THETA2_KEYS}
      unit="°"
      locked={isLocked('theta2')}
      onCommit={(v) => dispatch({ type: 'setTheta2', deg: v })}
    />
  );
}

/** The assembly branch, open or crossed; hideLegend keeps "Branch" as the group's name only (the phone bar). */
export function BranchControl({
  state,
  dispatch,
  isLocked,
  hideLegend,
}: ControlsSectionProps & { hideLegend?: boolean }) {
  const t = useMessages();
  return (
    <Segmented
      legend={t.branch}
      value={state.design.branch}
      locked={isLocked('branch')}
      hideLegend={hideLegend}
      options={[
        { value: 'open', label: t.branchOpen },
        { value: 'crossed', label: t.branchCrossed },
      ]}
      onChange={(b) => dispatch({ type: 'setBranch', branch: b })}
    />
  );
}

/** The input angle θ2 and the assembly branch. */
export function InputSection(props: ControlsSectionProps) {
  const t = useMessages();
  return (
    <PanelSection holdOffScreen={props.state.motion.playing} id="sec-input" title={t.sectionInput}>
      <Theta2Control {...props} />
      <BranchControl {...props} />
    </PanelSection>
  );
}

/** A step button beside Play: an icon, named by its label. */
function StepButton({
  label,
  icon,
  disabled,
  onClick,
}: {
  label: string;
  icon: 'stepBack' | 'stepForward';
  disabled: boolean;
  onClick: () => void;
}) {
  return (
    <button type="button" className="icon-btn" aria-label={label} title={label} disabled={disabled} onClick={onClick}>
      <Icon name={icon} />
    </button>
  );
}

/** Step back, Play/Pause and step forward. */
export function PlayRow({
  state,
  dispatch,
  isLocked,
  onStep,
}: ControlsSectionProps & { onStep: (sign: 1 | -1) => void }) {
  const t = useMessages();
  const playLocked = isLocked('play');
  // A linkage that assembles nowhere has nothing to play (the canvas says why).
  const assembles = useMemo(() => assemblesAnywhere(inputRange(state.design.linkage)), [state.design.linkage]);
  return (
    <div className="play-row">
      <StepButton label={t.stepBack} icon="stepBack" disabled={isLocked('theta2')} onClick={() => onStep(-1)} />
      <button
        type="button"
        className={`btn btn-primary play-btn${playLocked ? ' is-locked' : ''}`}
        disabled={playLocked || !assembles}
        title={playLocked ? t.locked : assembles ? undefined : t.cannotAssembleAny}
        onClick={() => dispatch({ type: 'setPlaying', playing: !state.motion.playing })}
      >
        <Icon name={state.motion.playing && assembles ? 'pause' : 'play'} size={14} />
        <span>{state.motion.playing && assembles ? t.pause : t.play}</span>
      </button>
      <StepButton label={t.stepForward} icon="stepForward" disabled={isLocked('theta2')} onClick={() => onStep(1)} />
    </div>
  );
}

/** Props of AnimationSection: a section's props, the step handler, the layout and whether the input rocks. */
export interface AnimationSectionProps extends ControlsSectionProps {
  onStep: (sign: 1 | -1) => void;
  compact: boolean;
  rocking: boolean;
  /** Leave out Play and step (the phone bar holds them); default false. */
  withoutPlay?: boolean;
}

/** Play and step; in the full layout also the speed and direction; a note when the input only rocks. */
export function AnimationSection({ compact, rocking, withoutPlay = false, ...props }: AnimationSectionProps) {
  const t = useMessages();
  const { state, dispatch } = props;
  return (
    <PanelSection holdOffScreen={state.motion.playing} id="sec-anim" title={t.sectionAnimation}>
      {withoutPlay ? null : <PlayRow {...props} />}
      {!compact ? (
        <>
          <NumberControl
            field="speed"
            value={state.motion.speedDegPerFrame}
            min={SPEED_MIN}
            max={SPEED_MAX}
            step={SPEED_STEP}
            onCommit={(v) => dispatch({ type: 'setSpeed', degPerFrame: v })}
          />
          <Segmented<'1' | '-1'>
            legend={t.direction}
            value={String(state.motion.direction) as '1' | '-1'}
            options={[
              { value: '1', label: t.ccw },
              { value: '-1', label: t.cw },
            ]}
            onChange={(d) => dispatch({ type: 'setDirection', direction: Number(d) as Direction })}
          />
        </>
      ) : null}
      {rocking ? <p className="note">{t.rockingNote}</p> : null}
    </PanelSection>
  );
}

/** The coupler point: its distance along the coupler (on the lengths' range) and its angle. */
export function CouplerSection({ state, dispatch, isLocked, range }: ControlsSectionProps & { range: SliderRange }) {
  const t = useMessages();
  return (
    <PanelSection holdOffScreen={state.motion.playing} id="sec-coupler" title={t.sectionCoupler}>
      <NumberControl
        field="couplerDistance"
        value={state.design.coupler.distance}
        min={0}
        max={range.max}
        step={range.step}
        unit={state.design.lengthUnit}
        locked={isLocked('coupler')}
        onCommit={(v) => dispatch({ type: 'setCoupler', coupler: { distance: v } })}
      />
      <NumberControl
        field="couplerAngle"
        value={state.design.coupler.angleDeg}
        min={-180}
        max={180}
        step={1}
        turn={COUPLER_ANGLE_KEYS}
        unit="°"
        locked={isLocked('coupler')}
        onCommit={(v) => dispatch({ type: 'setCoupler', coupler: { angleDeg: v } })}
      />
    </PanelSection>
  );
}

/** The canvas's display toggles and the number of cycle samples (an unusual count from a link is kept listed). */
export function DisplaySection({ state, dispatch }: Omit<ControlsSectionProps, 'isLocked'>) {
  const t = useMessages();
  const choices = SAMPLE_CHOICES.includes(state.solver.samples)
    ? SAMPLE_CHOICES
    : [...SAMPLE_CHOICES, state.solver.samples].sort((a, b) => a - b);
  return (
    <PanelSection holdOffScreen={state.motion.playing} id="sec-display" title={t.sectionDisplay}>
      <FlagToggles
        flags={['showGrid', 'showAngles', 'showGhost', 'showTrace', 'showDeadCentres', 'showInstantCentres']}
        state={state.display}
        dispatch={dispatch}
      />
      <label className="inline-field">
        <span>{t.samples}</span>
        <select
          className="select select-small"
          value={String(state.solver.samples)}
          onChange={(e) => dispatch({ type: 'setSamples', samples: Number(e.target.value) })}
        >
          {choices.map((n) => (
            <option key={n} value={n}>
              {n + 1}
            </option>
          ))}
        </select>
      </label>
    </PanelSection>
  );
}
