import type { Plugin } from 'vite';

/** The folder beside fourbar-lab.js that holds the element's module, its lazy chunks and its workers. */
export const ELEMENT_DIR = 'fourbar-lab';

/** The element's module inside ELEMENT_DIR (the build's entry). */
export const ELEMENT_MODULE = `${ELEMENT_DIR}/element.js`;

/**
 * The classic script a page includes (`<script src="fourbar-lab.js">`, as before the element had chunks): it finds
 * its own URL (document.currentScript; under `type="module"` the page's script whose src names it) and imports the
 * element's module from beside it. That module, an ES module, imports its chunks (three.js and the Spatial page, the
 * Mechanisms page) relative to its own URL, only when an element shows their page.
 */
export function elementLoaderSource(modules: readonly string[]): string {
  return `/* <fourbar-lab>: loads ${ELEMENT_MODULE} from beside this script. */
(function () {
  var me = document.currentScript;
  if (!me) {
    var scripts = document.querySelectorAll('script[src]');
    for (var i = 0; i < scripts.length; i++) if (/fourbar-lab\\.js([?#]|$)/.test(scripts[i].src)) me = scripts[i];
  }
  var base = me ? me.src : document.baseURI;
  ${JSON.stringify(modules)}.forEach(function (m) {
    var url = new URL(m, base).href;
    import(url).catch(function (e) {
      console.error('fourbar-lab: could not load ' + url + ' (' + e + ')');
    });
  });
})();
`;
}

/** Writes fourbar-lab.js (elementLoaderSource, with the element's module and its static imports) beside its folder. */
export function elementLoader(): Plugin {
  return {
    name: 'fourbar-element-loader',
    apply: 'build',
    generateBundle(_, bundle) {
      const entry = bundle[ELEMENT_MODULE];
      if (entry?.type !== 'chunk') return this.error(`the element build has no ${ELEMENT_MODULE}`);
      const modules: string[] = [];
      const visit = (fileName: string) => {
        const chunk = bundle[fileName];
        if (modules.includes(fileName) || chunk?.type !== 'chunk') return;
        modules.push(fileName);
        chunk.imports.forEach(visit);
      };
      visit(ELEMENT_MODULE);
      this.emitFile({ type: 'asset', fileName: 'fourbar-lab.js', source: elementLoaderSource(modules) });
    },
  };
}
