import { createContext, useContext } from 'react';
import type { Theta2Scrub } from './useAnimation';

/** The θ2 drag of the simulator on screen (FramePoseProvider provides it); null outside one. */
export const Theta2ScrubContext = createContext<Theta2Scrub | null>(null);

/** The θ2 drag, or null where no simulator provides one (a control drawn on its own commits each value). */
export function useTheta2Scrub(): Theta2Scrub | null {
  return useContext(Theta2ScrubContext);
}
