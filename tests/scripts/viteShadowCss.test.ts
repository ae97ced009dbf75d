import { describe, expect, it } from 'vitest';
import { shadowCss } from '../../scripts/viteShadowCss';

describe('shadowCss', () => {
  it('turns page-level selectors into :host and leaves classes that merely contain the words', () => {
    expect(shadowCss(':root{--radius:8px}html,body,#root{margin:0}body{color:red}.embed-page,.body-x{a:b}')).toBe(
      ':host{--radius:8px}:host,:host,#root{margin:0}:host{color:red}.embed-page,.body-x{a:b}',
    );
  });

  it('measures heights on the host (cqh) and turns width/height media queries into container queries', () => {
    expect(
      shadowCss(
        '.a{height:calc(100vh - 8px)}@media (min-height:500px) and (min-width:561px){.b{c:d}}' +
          '@media (max-width: 560px){.c{d:e}}@media (prefers-reduced-motion:reduce){.d{e:f}}@media print{.e{f:g}}',
      ),
    ).toBe(
      '.a{height:calc(100cqh - 8px)}@container (min-height:500px) and (min-width:561px){.b{c:d}}' +
        '@container (max-width: 560px){.c{d:e}}@media (prefers-reduced-motion:reduce){.d{e:f}}@media print{.e{f:g}}',
    );
  });
});
