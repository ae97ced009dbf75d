import { cssVariables } from './tokens';

/** The part of a style declaration applyTokens writes to (document.documentElement.style in the browser). */
export interface CustomPropertyTarget {
  setProperty(name: string, value: string): void;
}

/**
 * Sets every CSS custom property of the design tokens (cssVariables) on target, so the stylesheets read
 * their colours, fonts and tool sizes from src/shared/theme/tokens.ts. Call once at startup, before the first render.
 */
export function applyTokens(target: CustomPropertyTarget): void {
  for (const [name, value] of Object.entries(cssVariables())) target.setProperty(name, value);
}
