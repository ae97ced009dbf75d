import './NumberField.css';
import { useEffect, useEffectEvent, useId, useState } from 'react';
import { fieldText, formatNumber } from '../format';
import { readNumberText } from './validateNumber';

/** Props of NumberField: its name and unit, the value, how a typed text is judged and what a valid one commits. */
export interface NumberFieldProps {
  /** Accessible name, also the visible label unless hideLabel. */
  label: string;
  /** The value shown while the person is not typing; null shows an empty field (and the placeholder). */
  value: number | null;
  /** Called with each accepted number that differs from value (-0 as 0). */
  onCommit: (value: number) => void;
  /**
   * The message for a refused text, from the text (trimmed, cut to ECHO_MAX_CHARS), the value kept (10 significant
   * digits, '' when none) and check's reason (null: not a number); it should name the field.
   */
  errorText: (text: string, kept: string, why: string | null) => string;
  /** Why a finite number is refused (out of range, say), or null; default accepts every finite number. */
  check?: (value: number) => string | null;
  /** Called when the field is emptied while it holds a value; absent: an empty text is refused as not a number. */
  onClear?: () => void;
  /** Commit each valid text as it is typed; default false: commit on Enter or when the field loses focus. */
  live?: boolean;
  /** Decimals shown (trailing zeros dropped); default the exact value. */
  decimals?: number;
  /**
   * Shown after the field (°, kg, N·m) and read after the label as part of the accessible name; '' keeps an empty
   * place, so the field lines up with its neighbours' in a column; default none.
   */
  unit?: string;
  placeholder?: string;
  /** Told when the field's message appears (with it) or goes (null), so a form can hold its action meanwhile. */
  onErrorChange?: (error: string | null) => void;
  /** Hide the label visually (it stays the accessible name); default false. */
  hideLabel?: boolean;
  /** Extra class of the root, for a page's layout; the field's own are num-field and num-field-*. */
  className?: string;
}

/**
 * A labelled text field for one number. It follows the value unless the person is typing; a text that is not a
 * number, or that check refuses, shows a message naming the field (errorText) and keeps the last valid value;
 * Escape restores the value. readNumberText does the reading.
 */
export function NumberField({
  label,
  value,
  onCommit,
  errorText,
  check,
  onClear,
  live = false,
  decimals,
  unit,
  placeholder,
  onErrorChange,
  hideLabel = false,
  className,
}: NumberFieldProps) {
  const id = useId();
  const shown = value === null ? '' : fieldText(value, decimals);
  /** The text as typed, or null while the field shows the value. */
  const [draft, setDraft] = useState<string | null>(null);
  const [error, setError] = useState<string | null>(null);
  const [focused, setFocused] = useState(false);
  const tell = useEffectEvent((e: string | null) => onErrorChange?.(e));
  useEffect(() => tell(error), [error]);
  // A field that goes (a row removed, a mode left) takes its message with it.
  useEffect(() => () => tell(null), []);
  const [lastValue, setLastValue] = useState(value);
  if (value !== lastValue) {
    // Follow outside changes (a drag, an undo, the URL) unless the person is typing; adjusted while rendering, not
    // in an effect, as NumberControl does.
    setLastValue(value);
    if (!focused) {
      setDraft(null);
      setError(null);
    }
  }
  /** Commits text when it reads as a value (or as empty, where allowed); otherwise says why. True when taken. */
  const take = (text: string): boolean => {
    const r = readNumberText(text, { check, allowEmpty: onClear !== undefined });
    if (r.kind === 'refused') {
      setError(errorText(r.text, value === null ? '' : formatNumber(value, 10), r.why));
      return false;
    }
    setError(null);
    if (r.kind === 'empty') {
      if (value !== null) onClear?.();
    } else if (r.value !== value) {
      onCommit(r.value);
    }
    return true;
  };
  const commitDraft = () => {
    if (draft !== null && take(draft)) setDraft(null);
  };
  const errorId = `${id}-error`;
  return (
    <div className={`num-field${error ? ' is-invalid' : ''}${className ? ` ${className}` : ''}`}>
      <label htmlFor={id} className={hideLabel ? 'sr-only' : 'num-field-label'}>
        {label}
        {unit ? <span className="sr-only"> ({unit})</span> : null}
      </label>
      <span className="num-field-box">
        <input
          id={id}
          className="num-field-input"
          type="text"
          inputMode="decimal"
          autoComplete="off"
          spellCheck={false}
          value={draft ?? shown}
          placeholder={placeholder}
          aria-invalid={error ? true : undefined}
          aria-describedby={error ? errorId : undefined}
          onFocus={() => setFocused(true)}
          onBlur={() => {
            setFocused(false);
            // A live field has committed its text already; a refused one stays as typed, beside its message.
            if (!live) commitDraft();
            else if (!error) setDraft(null);
          }}
          onChange={(e) => {
            setDraft(e.target.value);
            if (live) take(e.target.value);
          }}
          onKeyDown={(e) => {
            if (e.key === 'Enter' && !live) commitDraft();
            if (e.key === 'Escape') {
              setDraft(null);
              setError(null);
            }
          }}
        />
        {unit !== undefined ? (
          <span className="num-field-unit" aria-hidden="true">
            {unit}
          </span>
        ) : null}
      </span>
      {error ? (
        <p id={errorId} className="num-field-error" role="alert">
          {error}
        </p>
      ) : null}
    </div>
  );
}
