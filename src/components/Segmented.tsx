import './Segmented.css';
import { useId } from 'react';

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
  hideLegend,
}: SegmentedProps<T>) {
  const name = useId();
  return (
    <fieldset className="segmented" disabled={disabled}>
      <legend className={hideLegend ? 'sr-only' : 'segmented-legend'}>{legend}</legend>
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
