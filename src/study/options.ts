/** NR tolerances the lab traces each NR method over and the app offers (relative for the project's NR, absolute for seed). */
export const LAB_TOLERANCES: readonly number[] = [1e-3, 1e-6, 1e-9, 1e-12, 1e-15];

/** Input steps (degrees) the lab can sweep the cycle with. */
export const LAB_STEPS_DEG: readonly number[] = [0.1, 1, 5];
