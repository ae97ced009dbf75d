import { useId, useState } from 'react';
import { parseDecimal } from '../../../shared/ui/validateNumber';
import { fieldText, formatNumber, truncateText } from '../../../shared/format';

/** Props of DecimalField: its accessible name, value, what a bad text says, and an optional extra check. */
export interface DecimalFieldProps {
  /** Accessible name (also the visible label unless hideLabel). */
  label: string;
  value: number;
  onCommit: (value: number) => void;
  /** The message for a refused text: the text, the value kept (formatted) and check's reason (null: not a number). */
  errorText: (text: string, kept: string, why: string | null) => string;
  /** Why an otherwise good number is refused (out of range), or null. */
  check?: (value: number) => string | null;
  /** Decimals shown (trailing zeros dropped); absent: the exact value. */
  decimals?: number;
  hideLabel?: boolean;
  unit?: string;
  /** Class of the input (e2e and CSS). */
  className?: string;
}

/** Most characters of a refused text echoed in the message. */
const ECHO_CHARS = 24;

/**
 * A text field for one number: it follows the value unless the person is typing, commits each valid text, and for a
 * bad one keeps the last valid value and says why, naming the field and the text. Escape restores the value.
 */
export function DecimalField({
  label,
  value,
  onCommit,
  errorText,
  check,
  decimals,
  hideLabel,
  unit,
  className,
}: DecimalFieldProps) {
  const id = useId();
  const shown = fieldText(value, decimals);
  const [draft, setDraft] = useState(shown);
  const [error, setError] = useState<string | null>(null);
  const [focused, setFocused] = useState(false);
  const [lastValue, setLastValue] = useState(value);
  if (value !== lastValue) {
    // Follow outside changes (a drag, a URL) unless the person is typing; adjusted while rendering, not in an effect.
    setLastValue(value);
    if (!focused) {
      setDraft(shown);
      setError(null);
    }
  }
  const onText = (text: string) => {
    setDraft(text);
    const v = parseDecimal(text);
    const why = Number.isFinite(v) ? (check?.(v) ?? null) : null;
    if (Number.isFinite(v) && why === null) {
      setError(null);
      if (v !== value) onCommit(v === 0 ? 0 : v);
      return;
    }
    setError(errorText(truncateText(text.trim(), ECHO_CHARS), formatNumber(value, 10), why));
  };
  return (
    <span className={`synmode-field${error ? ' synmode-field-invalid' : ''}`}>
      <label htmlFor={id} className={hideLabel ? 'sr-only' : 'synmode-field-label'}>
        {label}
      </label>
      <span className="synmode-field-box">
        <input
          id={id}
          className={className ? `synmode-input ${className}` : 'synmode-input'}
          type="text"
          inputMode="decimal"
          autoComplete="off"
          spellCheck={false}
          value={draft}
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
        {unit ? <span aria-hidden="true">{unit}</span> : null}
      </span>
      {error ? (
        <span id={`${id}-error`} className="synmode-field-error" role="alert">
          {error}
        </span>
      ) : null}
    </span>
  );
}
