import '../../../shared/ui/NumberField.css';
import { useId, useState } from 'react';
import { expressionTextProblem } from '../../../shared/state/slices/synFunctionSlice';
import type { ExpressionParser } from './useExpressionParser';
import type { FunctionMessages } from './functionMessages';
import { expressionProblemText } from './expressionText';

/** Props of ExpressionField: the expression in the state, the parser, and what a good one does. */
export interface ExpressionFieldProps {
  value: string;
  parse: NonNullable<ExpressionParser>;
  onCommit: (expression: string) => void;
  fm: FunctionMessages;
}

/**
 * The "y = f(x)" field: each text that parses as a formula of x is committed; any other keeps the last good one
 * and says why, naming the expression as typed. Escape restores the last good one.
 */
export function ExpressionField({ value, parse, onCommit, fm }: ExpressionFieldProps) {
  const id = useId();
  const [draft, setDraft] = useState(value);
  const [error, setError] = useState<string | null>(null);
  const [lastValue, setLastValue] = useState(value);
  if (value !== lastValue) {
    // Follow outside changes (a URL) unless the text typed is that value's own draft; adjusted while rendering.
    setLastValue(value);
    if (value !== draft.trim()) {
      setDraft(value);
      setError(null);
    }
  }
  const onText = (text: string) => {
    setDraft(text);
    const lexical = expressionTextProblem(text);
    const parsed = lexical ? null : parse(text);
    const problem = lexical ?? (parsed && !parsed.ok ? parsed.problem : null);
    if (problem) {
      setError(expressionProblemText(fm, text.trim(), problem));
      return;
    }
    setError(null);
    if (text.trim() !== value) onCommit(text.trim());
  };
  return (
    <div className={`num-field synmode-expression${error ? ' is-invalid' : ''}`}>
      <label htmlFor={id} className="num-field-label">
        {fm.expressionLabel}
      </label>
      <input
        id={id}
        className="num-field-input"
        type="text"
        autoComplete="off"
        autoCapitalize="off"
        spellCheck={false}
        value={draft}
        aria-invalid={error ? true : undefined}
        aria-describedby={`${id}-help${error ? ` ${id}-error` : ''}`}
        data-testid="fx-field"
        onChange={(e) => onText(e.target.value)}
        onKeyDown={(e) => {
          if (e.key === 'Escape') {
            setDraft(value);
            setError(null);
          }
        }}
      />
      <p id={`${id}-help`} className="note">
        {fm.expressionHelp}
      </p>
      {error ? (
        <p id={`${id}-error`} className="num-field-error" role="alert" data-testid="fx-error">
          {error}
        </p>
      ) : null}
    </div>
  );
}
