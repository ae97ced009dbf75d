import './NumberControl.css';
import { useEffect, useId, useRef, useState } from 'react';
import type { KeyboardEvent, RefObject } from 'react';
import type { FieldName } from './validateNumber';
import { ECHO_MAX_CHARS, parseField } from './validateNumber';
import { fieldText, formatNumber, truncateText } from '../format';
import { useMessages } from '../i18n/MessagesContext';
import type { TurnKeys } from './sliderKeys';
import { turnKeyValue } from './sliderKeys';

/** Props of NumberControl: the field, its value (field units) and slider range; onCommit gets only valid values. */
export interface NumberControlProps {
  field: FieldName;
  value: number;
  min: number;
  max: number;
  step: number;
  onCommit: (value: number) => void;
  disabled?: boolean;
  /** Locked by an embed: shown read-only with a lock mark (class is-locked), the slider disabled. */
  locked?: boolean;
  /** Decimals the field shows (trailing zeros dropped); absent: the exact value. */
  decimals?: number;
  /** Unit text after the field, e.g. '°'. */
  unit?: string;
  /** An angle on the circle [min, max): the slider's keys step by turn.step and wrap around (turnKeyValue). */
  turn?: TurnKeys;
  /**
   * A drag of the slider shown ahead of the state: each value goes to drag.move instead of onCommit, and the
   * slider's release (its change event) to drag.end. The keys still commit through onCommit.
   */
  drag?: SliderDrag | null;
}

/** Where a slider drag goes (see NumberControlProps.drag). */
export interface SliderDrag {
  move(value: number): void;
  end(): void;
}

function LockMark() {
  return (
    <svg className="lock-mark" width="11" height="11" viewBox="0 0 16 16" aria-hidden="true" focusable="false">
      <path
        d="M4.5 7V5a3.5 3.5 0 0 1 7 0v2h1a1 1 0 0 1 1 1v6a1 1 0 0 1-1 1h-9a1 1 0 0 1-1-1V8a1 1 0 0 1 1-1zm1.8 0h3.4V5a1.7 1.7 0 0 0-3.4 0z"
        fill="currentColor"
      />
    </svg>
  );
}

/** What a field's text reads as: a valid value, or the message naming the field, the text and the problem. */
export type FieldRead = { ok: true; value: number } | { ok: false; message: string };

/** The field's text as typed, its error, and what the field's events do with them. */
export interface FieldDraft {
  draft: string;
  error: string | null;
  onText: (text: string) => void;
  onFocus: () => void;
  onBlur: () => void;
  /** Restores the last valid value's text. */
  onEscape: () => void;
  clearError: () => void;
}

/**
 * The text of a number field: it follows the value unless the person is typing, commits each text that reads
 * (read) as a new value, and for a bad one keeps the last valid value and shows read's message.
 */
export function useFieldDraft(
  value: number,
  decimals: number | undefined,
  editable: boolean,
  read: (text: string) => FieldRead,
  onCommit: (value: number) => void,
): FieldDraft {
  const shown = fieldText(value, decimals);
  const [draft, setDraft] = useState(shown);
  const [error, setError] = useState<string | null>(null);
  const [focused, setFocused] = useState(false);
  const [shownValue, setShownValue] = useState(value);

  if (value !== shownValue) {
    // Follow outside changes (slider, preset, animation) unless the person is typing a different value; a field
    // that is locked or disabled cannot be typed in, even if it kept the focus it had before the lock came.
    // Adjusted while rendering, not in an effect: an effect's update would outlive each input of a burst
    // and React would count them as nested updates (error #185).
    setShownValue(value);
    if (!focused || !editable) {
      setDraft(shown);
      setError(null);
    }
  }

  const onText = (text: string) => {
    setDraft(text);
    const r = read(text);
    if (r.ok) {
      setError(null);
      if (r.value !== value) onCommit(r.value);
    } else setError(r.message);
  };
  return {
    draft,
    error,
    onText,
    onFocus: () => setFocused(true),
    onBlur: () => {
      setFocused(false);
      if (!error) setDraft(shown);
    },
    onEscape: () => {
      setDraft(shown);
      setError(null);
    },
    clearError: () => setError(null),
  };
}

/** The slider's ref: its release (the native change event, which React folds into onChange) ends drag. */
function useSliderRelease(drag: SliderDrag | null) {
  const ref = useRef<HTMLInputElement>(null);
  useEffect(() => {
    const slider = ref.current;
    if (!drag || !slider) return;
    const onRelease = () => drag.end();
    slider.addEventListener('change', onRelease);
    return () => slider.removeEventListener('change', onRelease);
  }, [drag]);
  return ref;
}

/** The field's label, with a lock mark (and its text for screen readers) when an embed locked the value. */
function NumberLabel({ htmlFor, label, locked }: { htmlFor: string; label: string; locked: boolean }) {
  const t = useMessages();
  return (
    <label className="numctl-label" htmlFor={htmlFor} title={locked ? `${label} (${t.locked})` : undefined}>
      {label}
      {locked ? (
        <>
          <span className="sr-only"> ({t.locked})</span>
          <LockMark />
        </>
      ) : null}
    </label>
  );
}

/** Props of NumberControlView: the label, the field's draft, the unit and the slider (its value and what a move does). */
export interface NumberControlViewProps {
  label: string;
  field: FieldDraft;
  /** Unit text after the field ('°'); absent: no unit box ('' keeps an empty one, so fields line up). */
  unit?: string;
  disabled?: boolean;
  locked?: boolean;
  /** The slider element (NumberControl listens for its release). */
  sliderRef?: RefObject<HTMLInputElement | null>;
  slider: {
    min: number;
    max: number;
    step: number;
    value: number;
    onKeyDown?: (e: KeyboardEvent<HTMLInputElement>) => void;
    /** The slider moved to a value (a number, maybe NaN). */
    onSlide: (value: number) => void;
  };
}

/**
 * The look of a number control (NumberControl, the spatial page's fields): the label and the text field with its
 * unit on one row, the slider under them (its value clamped to its range), and the field's error (role alert).
 */
export function NumberControlView({
  label,
  field,
  unit,
  disabled = false,
  locked = false,
  sliderRef,
  slider,
}: NumberControlViewProps) {
  const id = useId();
  const { draft, error } = field;
  return (
    <div className={`numctl${error ? ' numctl-invalid' : ''}${locked ? ' is-locked' : ''}`}>
      <div className="numctl-row">
        <NumberLabel htmlFor={`${id}-field`} label={label} locked={locked} />
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
            readOnly={locked}
            aria-readonly={locked ? true : undefined}
            aria-disabled={locked ? true : undefined}
            aria-invalid={error ? true : undefined}
            aria-describedby={error ? `${id}-error` : undefined}
            onFocus={field.onFocus}
            onBlur={field.onBlur}
            onChange={(e) => {
              if (!locked) field.onText(e.target.value);
            }}
            onKeyDown={(e) => {
              if (e.key === 'Escape') field.onEscape();
            }}
          />
          {unit !== undefined ? (
            <span className="numctl-unit" aria-hidden="true">
              {unit}
            </span>
          ) : null}
        </span>
      </div>
      <input
        ref={sliderRef}
        className="numctl-slider"
        type="range"
        aria-label={label}
        min={slider.min}
        max={slider.max}
        step={slider.step}
        value={Math.min(slider.max, Math.max(slider.min, slider.value))}
        disabled={disabled || locked}
        onKeyDown={slider.onKeyDown}
        onChange={(e) => slider.onSlide(Number(e.target.value))}
      />
      {error ? (
        <p id={`${id}-error`} className="numctl-error" role="alert">
          {error}
        </p>
      ) : null}
    </div>
  );
}

/**
 * A slider and a numeric field for one value. Typing a bad value (empty, text, zero, negative, too large)
 * shows an inline message naming the field and the value (cut to ECHO_MAX_CHARS) and keeps the last valid
 * one; Escape restores it. The field shows the value to `decimals` when given, so Play shows 255.05, not 255.045227.
 */
export function NumberControl({
  field,
  value,
  min,
  max,
  step,
  onCommit,
  disabled = false,
  locked = false,
  decimals,
  unit,
  turn,
  drag = null,
}: NumberControlProps) {
  const t = useMessages();
  const sliderRef = useSliderRelease(drag);
  const read = (text: string): FieldRead => {
    const r = parseField(field, text);
    if (r.ok) return r;
    const e = r.error;
    const raw = truncateText(text.trim(), ECHO_MAX_CHARS);
    return {
      ok: false,
      message: `${t.fieldError(e, { raw, min: formatNumber(e.min), max: formatNumber(e.max) })} ${t.keepingLast(formatNumber(value, 10))}`,
    };
  };
  const draft = useFieldDraft(value, decimals, !locked && !disabled, read, onCommit);
  const label = t.fieldLabels[field];
  return (
    <NumberControlView
      label={label}
      field={draft}
      unit={unit || undefined}
      disabled={disabled}
      locked={locked}
      sliderRef={sliderRef}
      slider={{
        min,
        max,
        step,
        value,
        onKeyDown: (e) => {
          const next = turn ? turnKeyValue(e.key, value, min, max, turn) : null;
          if (next === null) return;
          e.preventDefault();
          draft.clearError();
          onCommit(next);
        },
        onSlide: (v) => {
          if (!Number.isFinite(v)) return;
          draft.clearError();
          if (drag) drag.move(v);
          else onCommit(field === 'theta2' || field === 'couplerAngle' || field === 'speed' ? v : Math.max(min, v));
        },
      }}
    />
  );
}
