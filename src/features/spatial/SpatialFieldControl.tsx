import '../../shared/ui/NumberControl.css';
import { useId, useState } from 'react';
import { parseDecimal } from '../../shared/decimal';
import { fieldText, truncateText } from '../../shared/format';
import type { SpatialField } from '../../shared/state/slices/spatialSlice';
import { SPATIAL_FIELDS, normalizeSpatial, spatialFieldProblem } from '../../shared/state/slices/spatialSlice';
import { ECHO_MAX_CHARS } from '../../shared/ui/validateNumber';
import type { SpatialMessages } from './spatialMessages';

/** The slider's range and step of a field (the typed field takes anything its spec allows). */
export interface SliderRange {
  min: number;
  max: number;
  step: number;
}

/** Props of SpatialFieldControl: the field, its value, the slider's range, the commit and the strings. */
export interface SpatialFieldControlProps {
  field: SpatialField;
  value: number;
  slider: SliderRange;
  onCommit: (value: number) => void;
  sm: SpatialMessages;
  /** Decimals the field shows (trailing zeros dropped); absent: the exact value. */
  decimals?: number;
  /** Locked by an embed: shown, not editable; default false. */
  locked?: boolean;
}

/** The allowed range of a field as text: (0, 180)°. */
export function rangeText(field: SpatialField): string {
  const f = SPATIAL_FIELDS[field];
  const n = (x: number) => (Math.abs(x) >= 1e6 ? x.toExponential(0) : String(x));
  return `${f.minOpen ? '(' : '['}${n(f.min)}, ${n(f.max)}${f.maxOpen ? ')' : ']'}${f.angle ? '°' : ''}`;
}

/**
 * A slider and a field for one spatial value. A typed value outside the field's range or not a number shows a
 * message naming the field and the text and keeps the last valid value; Escape restores it.
 */
export function SpatialFieldControl(props: SpatialFieldControlProps) {
  const { field, value, slider, onCommit, sm, decimals, locked = false } = props;
  const id = useId();
  const shown = fieldText(value, decimals);
  const [draft, setDraft] = useState(shown);
  const [error, setError] = useState<string | null>(null);
  const [focused, setFocused] = useState(false);
  const [shownValue, setShownValue] = useState(value);
  if (value !== shownValue) {
    // Follow outside changes (slider, preset, Play) unless the person is typing.
    setShownValue(value);
    if (!focused) {
      setDraft(shown);
      setError(null);
    }
  }
  const label = sm.fieldNames[field];
  const angle = SPATIAL_FIELDS[field].angle;
  const onText = (text: string) => {
    setDraft(text);
    const echo = truncateText(text.trim(), ECHO_MAX_CHARS);
    const x = parseDecimal(text);
    if (Number.isNaN(x)) {
      setError(sm.notNumber(label, echo));
      return;
    }
    const v = normalizeSpatial(field, x);
    if (spatialFieldProblem(field, v) !== null) {
      setError(sm.fieldError(label, echo, rangeText(field)));
      return;
    }
    setError(null);
    if (v !== value) onCommit(v);
  };
  const sliderValue = Math.min(slider.max, Math.max(slider.min, value));
  return (
    <div className={`numctl${error ? ' numctl-invalid' : ''}`}>
      <div className="numctl-row">
        <label className="numctl-label" htmlFor={`${id}-field`}>
          {label}
        </label>
        <span className="numctl-field-wrap">
          <input
            id={`${id}-field`}
            className="numctl-field"
            type="text"
            inputMode="decimal"
            autoComplete="off"
            spellCheck={false}
            value={draft}
            disabled={locked}
            aria-invalid={error ? true : undefined}
            aria-describedby={error ? `${id}-error` : undefined}
            onFocus={() => setFocused(true)}
            onBlur={() => {
              setFocused(false);
              if (!error) setDraft(shown);
            }}
            onChange={(e) => onText(e.target.value)}
            onKeyDown={(e) => {
              if (e.key === 'Escape') {
                setDraft(shown);
                setError(null);
              }
            }}
          />
          <span className="numctl-unit" aria-hidden="true">
            {angle ? '°' : ''}
          </span>
        </span>
      </div>
      <input
        className="numctl-slider"
        type="range"
        aria-label={label}
        min={slider.min}
        max={slider.max}
        step={slider.step}
        value={sliderValue}
        disabled={locked}
        onChange={(e) => {
          const v = normalizeSpatial(field, Number(e.target.value));
          if (spatialFieldProblem(field, v) !== null) return;
          setError(null);
          onCommit(v);
        }}
      />
      {error ? (
        <p id={`${id}-error`} className="numctl-error" role="alert">
          {error}
        </p>
      ) : null}
    </div>
  );
}
