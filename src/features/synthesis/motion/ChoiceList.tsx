import { useId } from 'react';

/** One entry of a ChoiceList: its text and a second line (defects, transmission). */
export interface ChoiceItem {
  label: string;
  detail: string;
}

/** Props of ChoiceList: the group's name, the entries, the chosen index and what choosing does. */
export interface ChoiceListProps {
  legend: string;
  items: readonly ChoiceItem[];
  chosen: number;
  onChoose: (index: number) => void;
  testId?: string;
}

/** A radio group of results (the four-bars of five poses, the crank pivots of two): arrow keys move the choice. */
export function ChoiceList({ legend, items, chosen, onChoose, testId }: ChoiceListProps) {
  const name = useId();
  return (
    <fieldset className="synmode-choices" data-testid={testId}>
      <legend className="synmode-subtitle">{legend}</legend>
      {items.map((item, i) => (
        <label key={i} className={`synmode-choice${i === chosen ? ' is-on' : ''}`}>
          <input type="radio" name={name} checked={i === chosen} onChange={() => onChoose(i)} />
          <span>
            {item.label}
            <span className="synmode-choice-detail">{item.detail}</span>
          </span>
        </label>
      ))}
    </fieldset>
  );
}
