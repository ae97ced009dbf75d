import type { ReactNode } from 'react';

/** Props of Fact: its label, its value, and how it is shown. */
export interface FactProps {
  label: ReactNode;
  children: ReactNode;
  /** Spans the panel's two columns. */
  wide?: boolean;
  /** The value in the monospaced figures' font. */
  mono?: boolean;
  /** data-testid of the value (e2e reads it). */
  testId?: string;
}

/** One labelled value of a facts list (`<dl className="facts">`). */
export function Fact({ label, children, wide = false, mono = false, testId }: FactProps) {
  return (
    <div className={wide ? 'fact fact-wide' : 'fact'}>
      <dt>{label}</dt>
      <dd className={mono ? 'mono' : undefined} data-testid={testId}>
        {children}
      </dd>
    </div>
  );
}
