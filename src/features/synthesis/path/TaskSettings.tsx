import type { Dispatch } from 'react';
import type { Action, PathInput, PathTiming, SynPathState } from '../../../shared/state/appState';
import { formatNumber } from '../../../shared/format';
import { NumberField } from '../../../shared/ui/NumberField';
import { Segmented } from '../../../shared/ui/Segmented';
import type { SynthesisMessages } from '../synthesisMessages';
import { defaultPathBounds } from './pathTaskOf';

/** Props of TaskSettings: the task and its dispatch. */
export interface TaskSettingsProps {
  s: SynPathState;
  dispatch: Dispatch<Action>;
  /** Told when a field's message appears or goes (by the field's name): Synthesize waits while one shows. */
  onFieldError: (field: string, error: string | null) => void;
  st: SynthesisMessages;
}

/** Significant digits of a default bound in its placeholder. */
const SHOWN_DIGITS = 4;

/**
 * Timing (free, equal steps with the step in degrees, or a given θ2 per target in the table), the bounds (longest
 * link, coupler offset, the crank pivot's box; empty fields use defaults from the targets' size) and the input.
 */
export function TaskSettings({ s, dispatch, onFieldError, st }: TaskSettingsProps) {
  const d = defaultPathBounds(s.targets);
  const auto = (x: number) => st.autoValue(formatNumber(x, SHOWN_DIGITS));
  const positive = (label: string) => (x: number) => (x > 0 ? null : st.mustBePositive(label));
  const errorText = (text: string, _kept: string, why: string | null) => why ?? st.badNumber(text);
  const box = s.pivotBox ?? d.pivot;
  const setBox = (k: 'min' | 'max', axis: 'x' | 'y', v: number) => {
    const next = { min: { ...box.min }, max: { ...box.max } };
    next[k][axis] = v;
    if (next.min.x < next.max.x && next.min.y < next.max.y)
      dispatch({ type: 'setPathBounds', bounds: { pivotBox: next } });
  };
  const boxLabel = (k: 'min' | 'max', axis: 'x' | 'y') => `${axis} ${k === 'min' ? st.pivotMin : st.pivotMax}`;
  const boxField = (k: 'min' | 'max', axis: 'x' | 'y') => (
    <NumberField
      label={boxLabel(k, axis)}
      value={s.pivotBox ? s.pivotBox[k][axis] : null}
      placeholder={formatNumber(d.pivot[k][axis], SHOWN_DIGITS)}
      className="syn-field"
      errorText={errorText}
      check={(v) => {
        const other = k === 'min' ? box.max[axis] : box.min[axis];
        if (k === 'min' ? v < other : v > other) return null;
        return st.mustBeMore(boxLabel('max', axis), boxLabel('min', axis), formatNumber(other, 10));
      }}
      onCommit={(v) => setBox(k, axis, v)}
      onClear={() => dispatch({ type: 'setPathBounds', bounds: { pivotBox: null } })}
      onErrorChange={(e) => onFieldError(boxLabel(k, axis), e)}
    />
  );
  return (
    <section className="card syn-card" aria-labelledby="syn-task-title">
      <h3 id="syn-task-title" className="sr-only">
        {st.timingLegend}
      </h3>
      <Segmented<PathTiming>
        legend={st.timingLegend}
        value={s.timing}
        options={[
          { value: 'free', label: st.timingFree },
          { value: 'step', label: st.timingStep },
          { value: 'given', label: st.timingGiven },
        ]}
        onChange={(timing) => dispatch({ type: 'setTiming', timing })}
      />
      {s.timing === 'step' ? (
        <NumberField
          label={st.stepLabel}
          value={s.timingStepDeg}
          className="syn-field"
          errorText={errorText}
          check={(v) => (v !== 0 && Math.abs(v) <= 180 ? null : st.stepRule)}
          onCommit={(v) => dispatch({ type: 'setTimingStep', stepDeg: v })}
          onErrorChange={(e) => onFieldError(st.stepLabel, e)}
        />
      ) : null}
      <fieldset className="syn-bounds">
        <legend className="syn-field-label">{st.boundsTitle}</legend>
        <NumberField
          label={st.boundLength}
          value={s.boundLength}
          placeholder={auto(d.length)}
          className="syn-field"
          errorText={errorText}
          check={positive(st.boundLength)}
          onCommit={(v) => dispatch({ type: 'setPathBounds', bounds: { boundLength: v } })}
          onErrorChange={(e) => onFieldError(st.boundLength, e)}
          onClear={() => dispatch({ type: 'setPathBounds', bounds: { boundLength: null } })}
        />
        <NumberField
          label={st.boundCoupler}
          value={s.boundCoupler}
          placeholder={auto(d.coupler)}
          className="syn-field"
          errorText={errorText}
          check={positive(st.boundCoupler)}
          onCommit={(v) => dispatch({ type: 'setPathBounds', bounds: { boundCoupler: v } })}
          onErrorChange={(e) => onFieldError(st.boundCoupler, e)}
          onClear={() => dispatch({ type: 'setPathBounds', bounds: { boundCoupler: null } })}
        />
        <div className="syn-box" role="group" aria-label={st.pivotBox}>
          <span className="syn-field-label">{st.pivotBox}</span>
          <div className="syn-box-grid">
            {boxField('min', 'x')}
            {boxField('min', 'y')}
            {boxField('max', 'x')}
            {boxField('max', 'y')}
          </div>
        </div>
      </fieldset>
      <Segmented<PathInput>
        legend={st.inputLegend}
        value={s.input}
        options={[
          { value: 'crank', label: st.inputCrank },
          { value: 'any', label: st.inputAny },
        ]}
        onChange={(input) => dispatch({ type: 'setPathInput', input })}
      />
    </section>
  );
}
