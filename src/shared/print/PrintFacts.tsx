/** One labelled value of a printed sheet: its label, its text as the panels show it, and a key e2e compares by. */
export interface PrintFact {
  label: string;
  value: string;
  /** A stable key (the sheet's data attribute), e.g. 'theta3'. */
  key: string;
  /** Across the facts' two columns. */
  wide?: boolean;
}

/** Props of PrintFacts: the facts and the data attribute that carries each key (default data-report). */
export interface PrintFactsProps {
  facts: readonly PrintFact[];
  attr?: `data-${string}`;
}

/** A printed sheet's facts, two columns of label over value (PrintSheet.css). */
export function PrintFacts({ facts, attr = 'data-report' }: PrintFactsProps) {
  return (
    <dl className="report-facts">
      {facts.map((f) => (
        <div key={f.key} className={f.wide ? 'report-fact report-fact-wide' : 'report-fact'}>
          <dt>{f.label}</dt>
          <dd {...{ [attr]: f.key }}>{f.value}</dd>
        </div>
      ))}
    </dl>
  );
}
