/** Panels an embed can show besides the canvas ('forces': the Forces toggle, force arrows and the numbers). */
export type EmbedPanel = 'controls' | 'info' | 'plots' | 'export' | 'forces';

/** Parameters an embed can lock (shown, not editable). */
export type LockableParam = 'r1' | 'r2' | 'r3' | 'r4' | 'theta2' | 'branch' | 'coupler' | 'play';

/** Embed-only options: which panels show and which parameters are locked. */
export interface EmbedOptions {
  panels: EmbedPanel[];
  locked: LockableParam[];
}

/** All embed panels in display order. */
export const EMBED_PANELS: readonly EmbedPanel[] = ['controls', 'info', 'plots', 'export', 'forces'];

/** All lockable parameters. */
export const LOCKABLE_PARAMS: readonly LockableParam[] = [
  'r1',
  'r2',
  'r3',
  'r4',
  'theta2',
  'branch',
  'coupler',
  'play',
];

/** An embed shows the controls and the plots, with nothing locked, unless the URL says otherwise. */
export const DEFAULT_EMBED: EmbedOptions = { panels: ['controls', 'plots'], locked: [] };
