import { useId, useState } from 'react';
import type { FieldName } from '../state/validate';
import { parseField } from '../state/validate';
import { formatNumber } from '../state/format';
import { useMessages } from './MessagesContext';

/** Props of NumberControl: the field, its value (field units) and slider range; onCommit gets only valid values. */
export interface NumberControlProps {
  field: FieldName;
  value: number;
  min: number;
  max: number;
  step: number;
  onCommit: (value: number) => void;
  disabled?: boolean;
  /** Unit text after the field, e.g. '°'. */
  unit?: string;
}

/**
 * A slider and a numeric field for one value. Typing a bad value (empty, text, zero, negative, too large)
 * shows an inline message naming the field and the value and keeps the last valid one; Escape restores it.
 */
export function NumberControl({ field, value, min, max, step, onCommit, disabled = false, unit }: NumberControlProps) {
  const t = useMessages();
  const id = useId();
  const [draft, setDraft] = useState(String(value));
  const [error, setError] = useState<string | null>(null);
  const [focused, setFocused] = useState(false);
  const [shownValue, setShownValue] = useState(value);
  const label = t.fieldLabels[field];

  if (value !== shownValue) {
    // Follow outside changes (slider, preset, animation) unless the person is typing a different value.
    // Adjusted while rendering, not in an effect: an effect's update would outlive each input of a burst
    // and React would count them as nested updates (error #185).
    setShownValue(value);
    if (!focused) {
      setDraft(String(value));
      setError(null);
    }
  }

  const onText = (text: string) => {
    setDraft(text);
    const r = parseField(field, text);
    if (r.ok) {
      setError(null);
      if (r.value !== value) onCommit(r.value);
    } else {
      const e = r.error;
      setError(
        `${t.fieldError(e, { raw: text.trim() === '' ? '' : text.trim(), min: formatNumber(e.min), max: formatNumber(e.max) })} ${t.keepingLast(formatNumber(value, 10))}`,
      );
    }
  };

  const sliderValue = Math.min(max, Math.max(min, value));
  return (
    <div className={`numctl${error ? ' numctl-invalid' : ''}`}>
      <div className="numctl-row">
        <label className="numctl-label" htmlFor={`${id}-field`}>
          {label}
          {disabled ? <span className="locked"> ({t.locked})</span> : null}
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
            disabled={disabled}
            aria-invalid={error ? true : undefined}
            aria-describedby={error ? `${id}-error` : undefined}
            onFocus={() => setFocused(true)}
            onBlur={() => {
              setFocused(false);
              if (!error) setDraft(String(value));
            }}
            onChange={(e) => onText(e.target.value)}
            onKeyDown={(e) => {
              if (e.key === 'Escape') {
                setDraft(String(value));
                setError(null);
              }
            }}
          />
          {unit ? (
            <span className="numctl-unit" aria-hidden="true">
              {unit}
            </span>
          ) : null}
        </span>
      </div>
      <input
        className="numctl-slider"
        type="range"
        aria-label={label}
        min={min}
        max={max}
        step={step}
        value={sliderValue}
        disabled={disabled}
        onChange={(e) => {
          const v = Number(e.target.value);
          if (Number.isFinite(v)) {
            setError(null);
            onCommit(field === 'theta2' || field === 'couplerAngle' || field === 'speed' ? v : Math.max(min, v));
          }
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
