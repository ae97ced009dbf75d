import { useEffect, useEffectEvent, useState } from 'react';

/**
 * value itself, or while paced, value sampled every intervalMs (it starts from the value current when
 * pacing begins). Play uses it for the worker's pose request: the numbers and the NR plot follow the
 * animation a few times a second instead of costing a worker round trip and a chart redraw every frame.
 */
export function usePacedValue<T>(value: T, paced: boolean, intervalMs: number): T {
  const [held, setHeld] = useState(value);
  const [wasPaced, setWasPaced] = useState(paced);
  if (paced !== wasPaced) {
    // Adjusting state while rendering (no effect, no extra commit): pacing starts from the current value.
    setWasPaced(paced);
    setHeld(value);
  }
  const sample = useEffectEvent(() => setHeld(value));
  useEffect(() => {
    if (!paced) return;
    const id = setInterval(sample, intervalMs);
    return () => clearInterval(id);
  }, [paced, intervalMs]);
  return paced ? held : value;
}
