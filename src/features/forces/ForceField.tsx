import { useId, useState } from 'react';
import { fieldText, formatNumber } from '../../shared/format';
import { parseDecimal } from '../../shared/ui/validateNumber';
import type { ForcesMessages } from './forcesMessages';

/** Props of ForceField: its label and unit, the value, the accepted range and what a valid entry commits. */
export interface ForceFieldProps {
  label: string;
  /** Shown after the field (the length unit, kg, N·m…); part of the accessible name. */
  unit: string;
  value: number;
  min: number;
  max: number;
  onCommit: (value: number) => void;
  t: Pick<ForcesMessages, 'badNumber' | 'outOfRange'>;
  /** data-testid of the input (e2e). */
  testId?: string;
}

/**
 * A labelled decimal field with its unit, committed on Enter or when it loses focus: a bad text (not a number,
 * outside [min, max]) shows a message naming the field and keeps the last valid value; Escape restores it.
 */
export function ForceField({ label, unit, value, min, max, onCommit, t, testId }: ForceFieldProps) {
  const id = useId();
  const [draft, setDraft] = useState<string | null>(null);
  const [error, setError] = useState<string | null>(null);
  const commit = () => {
    if (draft === null) return;
    const x = parseDecimal(draft);
    const why = Number.isNaN(x)
      ? t.badNumber(label, draft.trim())
      : x < min || x > max
        ? t.outOfRange(label, formatNumber(min), formatNumber(max))
        : null;
    setError(why);
    if (why) return;
    setDraft(null);
    if (x !== value) onCommit(x === 0 ? 0 : x);
  };
  return (
    <div className={`frc-field${error ? ' frc-field-invalid' : ''}`}>
      <label htmlFor={id} className="frc-field-label">
        {label}
        {unit ? <span className="sr-only"> ({unit})</span> : null}
      </label>
      <span className="frc-field-wrap">
        <input
          id={id}
          type="text"
          inputMode="decimal"
          autoComplete="off"
          spellCheck={false}
          value={draft ?? fieldText(value)}
          aria-invalid={error ? true : undefined}
          aria-describedby={error ? `${id}-error` : undefined}
          data-testid={testId}
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
        <span className="frc-unit" aria-hidden="true">
          {unit}
        </span>
      </span>
      {error ? (
        <p id={`${id}-error`} className="frc-field-error" role="alert">
          {error}
        </p>
      ) : null}
    </div>
  );
}
