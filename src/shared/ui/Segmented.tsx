import './Segmented.css';
import { useId } from 'react';
import { useMessages } from '../i18n/MessagesContext';

/** One choice of a Segmented control. */
export interface SegmentedOption<T extends string> {
  value: T;
  label: string;
}

/** Props of Segmented: a labelled radio group drawn as a row of buttons. */
export interface SegmentedProps<T extends string> {
  legend: string;
  value: T;
  options: readonly SegmentedOption<T>[];
  onChange: (value: T) => void;
  disabled?: boolean;
  /** Locked by an embed: disabled, marked with class is-locked and '(locked)' after the legend. */
  locked?: boolean;
  /** Hide the legend visually (it stays the group's accessible name). */
  hideLegend?: boolean;
}

/** A radio group styled as segmented buttons; arrow keys move between choices as in any radio group. */
export function Segmented<T extends string>({
  legend,
  value,
  options,
  onChange,
  disabled,
  locked,
  hideLegend,
}: SegmentedProps<T>) {
  const name = useId();
  const t = useMessages();
  return (
    <fieldset className={`segmented${locked ? ' is-locked' : ''}`} disabled={disabled || locked}>
      <legend className={hideLegend ? 'sr-only' : 'segmented-legend'}>
        {legend}
        {locked ? <span className="locked"> ({t.locked})</span> : null}
      </legend>
      <div className="segmented-row">
        {options.map((o) => (
          <label key={o.value} className={`segmented-item${o.value === value ? ' is-on' : ''}`}>
            <input
              type="radio"
              name={name}
              value={o.value}
              checked={o.value === value}
              onChange={() => onChange(o.value)}
            />
            <span>{o.label}</span>
          </label>
        ))}
      </div>
    </fieldset>
  );
}
