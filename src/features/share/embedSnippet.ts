/** Escapes text for an HTML attribute value in double quotes (and for text between tags). */
export function escapeAttribute(s: string): string {
  return s
    .replace(/&/g, '&amp;')
    .replace(/"/g, '&quot;')
    .replace(/'/g, '&#39;')
    .replace(/</g, '&lt;')
    .replace(/>/g, '&gt;');
}

/** Embed size presets: three fixed frames and a responsive one that fills its column at the standard aspect. */
export type EmbedPresetId = 'compact' | 'standard' | 'large' | 'responsive';

/** One size preset: the frame's CSS pixel size (for the responsive one: its largest width and its aspect). */
export interface EmbedPreset {
  id: EmbedPresetId;
  width: number;
  height: number;
  responsive: boolean;
}

/**
 * The presets the Share panel offers. 600×450 and 760×520 are the frames the embed layout is tested in
 * (e2e/screens.spec.ts: the linkage, θ2, Play and the branch show unscrolled); standard is the default.
 */
export const EMBED_PRESETS: readonly EmbedPreset[] = [
  { id: 'compact', width: 600, height: 450, responsive: false },
  { id: 'standard', width: 760, height: 520, responsive: false },
  { id: 'large', width: 900, height: 640, responsive: false },
  { id: 'responsive', width: 760, height: 520, responsive: true },
];

/** The preset a new embed code starts from (760×520). */
export const DEFAULT_EMBED_PRESET: EmbedPreset = EMBED_PRESETS[1];

/** The smallest height of the responsive frame, CSS pixels: the compact preset's, so narrow columns stay usable. */
export const RESPONSIVE_MIN_HEIGHT = 450;

/**
 * The sandbox the snippet keeps: scripts (the widget is an app), same origin (its worker and storage where the
 * host allows), downloads (PNG and CSV export), and popups that leave the sandbox, so the "open full simulator"
 * link opens a normal tab. No top navigation, no forms, no modals.
 */
export const EMBED_SANDBOX =
  'allow-scripts allow-same-origin allow-downloads allow-popups allow-popups-to-escape-sandbox';

/** What embedSnippet writes: the widget's URL, the frame's accessible title, and the size preset. */
export interface EmbedSnippetOptions {
  src: string;
  title: string;
  preset: EmbedPreset;
}

function whole(name: string, x: number): number {
  if (!Number.isInteger(x) || x <= 0) throw new Error(`${name} must be a positive whole number of pixels, got ${x}`);
  return x;
}

/**
 * The HTML that embeds the widget: a sandboxed iframe with a title, allow="fullscreen" and loading="lazy";
 * fixed presets give width and height attributes, the responsive one an aspect-ratio wrapper div holding an
 * iframe at 100 % of it. Every attribute value is escaped. Throws for a size that is not a positive whole number.
 */
export function embedSnippet({ src, title, preset }: EmbedSnippetOptions): string {
  const width = whole('width', preset.width);
  const height = whole('height', preset.height);
  const common =
    `src="${escapeAttribute(src)}" title="${escapeAttribute(title)}" loading="lazy" allow="fullscreen" ` +
    `sandbox="${EMBED_SANDBOX}"`;
  if (!preset.responsive)
    return `<iframe ${common} width="${width}" height="${height}" style="border:0;max-width:100%"></iframe>`;
  return (
    `<div style="position:relative;width:100%;max-width:${width}px;aspect-ratio:${width}/${height};` +
    `min-height:${RESPONSIVE_MIN_HEIGHT}px">\n` +
    `  <iframe ${common} style="position:absolute;inset:0;width:100%;height:100%;border:0"></iframe>\n` +
    `</div>`
  );
}
