import type { Plugin } from 'vite';

/** Replaces every non-ASCII UTF-16 unit of JavaScript source with its \uXXXX escape. */
export function escapeNonAscii(code: string): string {
  return code.replace(/[^\x00-\x7f]/g, (c) => `\\u${c.charCodeAt(0).toString(16).padStart(4, '0')}`);
}

/**
 * Makes the output scripts pure ASCII. A page that loads the element with a plain <script src> decodes it in
 * the page's encoding when the server sends no charset, so "θ2" would turn into "Î¸2" on a page that is not
 * UTF-8. Escapes are the same characters in strings, template literals, regular expressions and identifiers.
 */
export function asciiOnly(): Plugin {
  return {
    name: 'fourbar-ascii-only',
    apply: 'build',
    enforce: 'post',
    generateBundle(_, bundle) {
      for (const f of Object.values(bundle)) if (f.type === 'chunk') f.code = escapeNonAscii(f.code);
    },
  };
}
