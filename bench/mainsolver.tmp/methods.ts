import type { SweepMethod } from './types';

/** The sweep methods, best default first (a dependency-free list, so the UI can offer them without the solver). */
export const SWEEP_METHODS: readonly SweepMethod[] = [
  'closed-form',
  'closed-form-polish',
  'newton',
  'newton-no-predictor',
  'seed',
];
