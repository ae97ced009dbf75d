import type { ReactNode } from 'react';
import { HoldingSection } from './Held';

/** Props of PanelSection: the heading's id and text, the section's content and class (default 'panel-section'). */
export interface PanelSectionProps {
  id: string;
  title: string;
  children: ReactNode;
  className?: string;
  /** While true (Play runs), the content keeps its last render while the section is off screen (HoldingSection). */
  holdOffScreen?: boolean;
}

/** A titled section of a sidebar (controls, or a results card), named by its heading for assistive technology. */
export function PanelSection({ id, title, children, className = 'panel-section', holdOffScreen }: PanelSectionProps) {
  return (
    <HoldingSection className={className} aria-labelledby={id} holdOffScreen={holdOffScreen}>
      <h2 id={id} className="section-title">
        {title}
      </h2>
      {children}
    </HoldingSection>
  );
}
