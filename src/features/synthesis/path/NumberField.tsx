import { useState } from 'react';

/** Props of NumberField: label, value (null shows the placeholder), and what a valid entry commits. */
export interface NumberFieldProps {
  label: string;
  value: number | null;
  /** Called with a finite number, or null when the field is emptied (only when allowEmpty). */
  onCommit: (value: number | null) => void;
  /** Refuses a value with this message, or accepts it (null). */
  check?: (value: number) => string | null;
  badNumber: (text: string) => string;
  placeholder?: string;
  allowEmpty?: boolean;
  /** Hide the label visually (it stays the field's accessible name). */
  hideLabel?: boolean;
  className?: string;
}

/** A decimal field that commits on Enter or blur; bad text shows a message naming it and keeps the last value. */
export function NumberField(props: NumberFieldProps) {
  const { label, value, onCommit, check, badNumber, placeholder, allowEmpty, hideLabel, className } = props;
  const [draft, setDraft] = useState<string | null>(null);
  const [error, setError] = useState<string | null>(null);
  const shown = draft ?? (value === null ? '' : String(value));
  const commit = () => {
    if (draft === null) return;
    const text = draft.trim();
    if (text === '' && allowEmpty) {
      setDraft(null);
      setError(null);
      onCommit(null);
      return;
    }
    const x = /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i.test(text) ? Number(text) : NaN;
    const why = Number.isFinite(x) ? (check?.(x) ?? null) : badNumber(text);
    setError(why);
    if (why) return;
    setDraft(null);
    onCommit(x);
  };
  return (
    <label className={`syn-field${className ? ` ${className}` : ''}`}>
      <span className={hideLabel ? 'sr-only' : 'syn-field-label'}>{label}</span>
      <input
        type="text"
        inputMode="decimal"
        value={shown}
        placeholder={placeholder}
        aria-invalid={error ? true : undefined}
        onChange={(e) => setDraft(e.target.value)}
        onBlur={commit}
        onKeyDown={(e) => {
          if (e.key === 'Enter') commit();
          if (e.key === 'Escape') {
            setDraft(null);
            setError(null);
          }
        }}
      />
      {error ? (
        <span className="syn-field-error" role="alert">
          {error}
        </span>
      ) : null}
    </label>
  );
}
