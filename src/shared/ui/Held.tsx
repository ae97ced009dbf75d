import { memo, useRef } from 'react';
import type { ComponentPropsWithoutRef, ReactNode } from 'react';
import { useOnScreen } from '../hooks/useOnScreen';

/** Props of Held: whether to keep the last rendered children, and the children. */
interface HeldProps {
  hold: boolean;
  children: ReactNode;
}

/**
 * Its children, or while hold is true those of its last render: React skips the subtree, so nothing in it renders
 * again until hold turns false (views in it that follow a store of their own still do).
 */
export const Held = memo(
  function Held({ children }: HeldProps) {
    return children;
  },
  (_previous, next) => next.hold,
);

/** Props of HoldingSection: a section element's props, and whether to hold its content while it is off screen. */
export interface HoldingSectionProps extends ComponentPropsWithoutRef<'section'> {
  /**
   * While true (Play runs: the state commits a few times a second), the content of a section off screen keeps its
   * last render and is brought up to date as it nears the view or when this turns false.
   */
  holdOffScreen?: boolean;
}

/** A section whose content can be held while it is off screen (HoldingSectionProps). */
export function HoldingSection({ holdOffScreen = false, children, ...props }: HoldingSectionProps) {
  const ref = useRef<HTMLElement>(null);
  const onScreen = useOnScreen(ref, holdOffScreen);
  return (
    <section ref={ref} {...props}>
      <Held hold={holdOffScreen && !onScreen}>{children}</Held>
    </section>
  );
}
