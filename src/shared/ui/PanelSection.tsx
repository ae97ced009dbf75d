import type { ReactNode } from 'react';

/** Props of PanelSection: the heading's id and text, the section's content and class (default 'panel-section'). */
export interface PanelSectionProps {
  id: string;
  title: string;
  children: ReactNode;
  className?: string;
}

/** A titled section of a sidebar (controls, or a results card), named by its heading for assistive technology. */
export function PanelSection({ id, title, children, className = 'panel-section' }: PanelSectionProps) {
  return (
    <section className={className} aria-labelledby={id}>
      <h2 id={id} className="section-title">
        {title}
      </h2>
      {children}
    </section>
  );
}
