/** Types of scripts/ensure-chromium.mjs (plain JavaScript) for playwright.config.ts and the UI benchmark. */
declare module '*/ensure-chromium.mjs' {
  /** A Chromium executable path, installing one when install is true; null when none can be found. */
  export function findChromium(options?: { install?: boolean }): Promise<string | null>;
}
