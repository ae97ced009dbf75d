import type { Plugin } from 'vite';

/** The string in src/app/element.tsx that the element build replaces with the widget's CSS. */
export const CSS_PLACEHOLDER = '__FOURBAR_LAB_CSS__';

const SIZE_QUERY = /^\s*\((min|max)-(width|height):[^)]*\)(\s*and\s*\((min|max)-(width|height):[^)]*\))*\s*$/;

/**
 * Rewrites page-level CSS for a shadow root whose host is a size container: :root, html and body become
 * :host, viewport heights (vh) become the host's (cqh), and media queries on width and height become
 * container queries, so the embed layout fits the element as it fits an iframe. Other media queries stay.
 */
export function shadowCss(css: string): string {
  return css
    .replace(/:root\b/g, ':host')
    .replace(/(^|[{},;\s>])(html|body)(?=[\s,{.:[>])/g, '$1:host')
    .replace(/(\d*\.?\d+)vh\b/g, '$1cqh')
    .replace(/@media([^{]*)\{/g, (all, cond: string) => (SIZE_QUERY.test(cond) ? `@container ${cond.trim()}{` : all));
}

/**
 * For the custom element: takes the CSS the build extracted, rewrites it with shadowCss, writes it into the
 * script in place of CSS_PLACEHOLDER and drops the CSS file, so the element is one script whose styles live
 * only in its shadow root. Fails the build when the placeholder or the CSS is missing.
 */
export function cssIntoShadowRoot(): Plugin {
  return {
    name: 'fourbar-css-into-shadow-root',
    apply: 'build',
    enforce: 'post',
    generateBundle(_, bundle) {
      const css = Object.values(bundle).filter((f) => f.type === 'asset' && f.fileName.endsWith('.css'));
      const js = Object.values(bundle).filter((f) => f.type === 'chunk');
      if (css.length === 0) this.error('no CSS was extracted for the element');
      const text = shadowCss(css.map((f) => (f.type === 'asset' ? String(f.source) : '')).join('\n'));
      for (const f of css) delete bundle[f.fileName];
      let replaced = 0;
      for (const chunk of js) {
        if (chunk.type !== 'chunk' || !chunk.code.includes(CSS_PLACEHOLDER)) continue;
        chunk.code = chunk.code.split(`"${CSS_PLACEHOLDER}"`).join(JSON.stringify(text));
        chunk.code = chunk.code.split(`'${CSS_PLACEHOLDER}'`).join(JSON.stringify(text));
        chunk.code = chunk.code.split(`\`${CSS_PLACEHOLDER}\``).join(JSON.stringify(text));
        replaced += 1;
      }
      if (replaced !== 1) this.error(`expected the CSS placeholder in one chunk, found it in ${replaced}`);
    },
  };
}
