import { describe, expect, it } from 'vitest';
import { ELEMENT_MODULE, elementLoaderSource } from '../../scripts/viteElementLoader';

/** The URLs the loader imports, run against a fake document (import() swapped for a recorder). */
function importsOf(doc: { currentScript: { src: string } | null; scripts: string[]; baseURI: string }): string[] {
  const seen: string[] = [];
  const source = elementLoaderSource([ELEMENT_MODULE, 'fourbar-lab/widget-abc.js']).replace('import(url)', 'load(url)');
  const document = {
    currentScript: doc.currentScript,
    baseURI: doc.baseURI,
    querySelectorAll: () => doc.scripts.map((src) => ({ src })),
  };
  const load = (url: string) => {
    seen.push(url);
    return Promise.resolve();
  };
  new Function('document', 'load', source)(document, load);
  return seen;
}

describe('elementLoaderSource', () => {
  it('imports the element’s module and its chunks from beside the classic script, wherever the page is', () => {
    expect(
      importsOf({
        currentScript: { src: 'https://cdn.test/lib/fourbar-lab.js?v=2' },
        scripts: [],
        baseURI: 'https://course.test/week3/',
      }),
    ).toEqual(['https://cdn.test/lib/fourbar-lab/element.js', 'https://cdn.test/lib/fourbar-lab/widget-abc.js']);
  });

  it('under type="module" (no currentScript) finds its own script among the page’s by its name', () => {
    expect(
      importsOf({
        currentScript: null,
        scripts: ['https://course.test/app.js', 'https://cdn.test/x/fourbar-lab.js'],
        baseURI: 'https://course.test/week3/',
      })[0],
    ).toBe('https://cdn.test/x/fourbar-lab/element.js');
  });
});
