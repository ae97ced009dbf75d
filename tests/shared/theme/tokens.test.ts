import { readFileSync, readdirSync } from 'node:fs';
import { join, relative } from 'node:path';
import { describe, expect, it } from 'vitest';
import { applyTokens } from '../../../src/shared/theme/applyTokens';
import { COLORS, cssVariables } from '../../../src/shared/theme/tokens';

// One source for colours: src/shared/theme/tokens.ts. The stylesheets read them through CSS variables that
// applyTokens sets at startup, so a stylesheet holds no colour of its own; the canvas renderer reads them
// through shared/canvas/canvasTheme.ts, so its source holds none either.

const SRC = join(import.meta.dirname, '../../../src');

function filesUnder(dir: string, ext: string): string[] {
  return readdirSync(dir, { withFileTypes: true, recursive: true })
    .filter((e) => e.isFile() && e.name.endsWith(ext))
    .map((e) => join(e.parentPath, e.name));
}

/** The 148 named colours of CSS Color 4 (transparent and currentcolor are not colours of their own). */
const NAMED_COLORS =
  `aliceblue antiquewhite aqua aquamarine azure beige bisque black blanchedalmond blue blueviolet brown
burlywood cadetblue chartreuse chocolate coral cornflowerblue cornsilk crimson cyan darkblue darkcyan darkgoldenrod
darkgray darkgreen darkgrey darkkhaki darkmagenta darkolivegreen darkorange darkorchid darkred darksalmon darkseagreen
darkslateblue darkslategray darkslategrey darkturquoise darkviolet deeppink deepskyblue dimgray dimgrey dodgerblue
firebrick floralwhite forestgreen fuchsia gainsboro ghostwhite gold goldenrod gray green greenyellow grey honeydew
hotpink indianred indigo ivory khaki lavender lavenderblush lawngreen lemonchiffon lightblue lightcoral lightcyan
lightgoldenrodyellow lightgray lightgreen lightgrey lightpink lightsalmon lightseagreen lightskyblue lightslategray
lightslategrey lightsteelblue lightyellow lime limegreen linen magenta maroon mediumaquamarine mediumblue mediumorchid
mediumpurple mediumseagreen mediumslateblue mediumspringgreen mediumturquoise mediumvioletred midnightblue mintcream
mistyrose moccasin navajowhite navy oldlace olive olivedrab orange orangered orchid palegoldenrod palegreen
paleturquoise palevioletred papayawhip peru pink plum powderblue purple rebeccapurple red rosybrown royalblue
saddlebrown salmon sandybrown seagreen seashell sienna silver skyblue slateblue slategray slategrey snow springgreen
steelblue tan teal thistle tomato turquoise violet wheat white whitesmoke yellow yellowgreen`.split(/\s+/);

/** Colour literals in CSS declaration values: hex, rgb/hsl/hwb/lab/lch/oklab/oklch/color() functions, named colours. */
function colorLiterals(css: string): string[] {
  const body = css.replace(/\/\*[\s\S]*?\*\//g, '');
  const values = [...body.matchAll(/(?:^|[;{])\s*(--)?[\w-]+\s*:\s*([^;{}]+)/g)].map((m) => m[2]);
  const out: string[] = [];
  for (const v of values) {
    const stripped = v.replace(/'[^']*'|"[^"]*"/g, '');
    for (const m of stripped.matchAll(/#[0-9a-f]{3,8}\b|\b(?:rgba?|hsla?|hwb|lab|lch|oklab|oklch|color)\([^)]*\)/gi))
      out.push(m[0]);
    for (const w of stripped.toLowerCase().matchAll(/(?<![\w-])[a-z]+(?![\w-])/g))
      if (NAMED_COLORS.includes(w[0])) out.push(w[0]);
  }
  return out;
}

describe('colorLiterals (the checker)', () => {
  it('finds hex, functional and named colours in values, and nothing in selectors, names or fonts', () => {
    const css = `.red-box:hover { color: #fff; background: rgba(0, 0, 0, 0.5); border: 1px solid red; }
      /* white */ .tan { font-family: 'Segoe UI', sans-serif; outline-color: currentColor; --x: hsl(1 2% 3%) }`;
    expect(colorLiterals(css)).toEqual(['#fff', 'rgba(0, 0, 0, 0.5)', 'red', 'hsl(1 2% 3%)']);
  });
});

describe('stylesheets', () => {
  const sheets = filesUnder(SRC, '.css');
  const tokenValues = new Set(Object.values(COLORS).map((c) => c.toLowerCase().replace(/\s+/g, '')));

  it('exist per component, and the old global styles.css is gone', () => {
    const names = sheets.map((f) => relative(SRC, f));
    expect(names).not.toContain('styles.css');
    expect(names.length).toBeGreaterThanOrEqual(10);
  });

  it('hold no colour that is not a token (in practice: none at all)', () => {
    const strays = sheets.flatMap((f) =>
      colorLiterals(readFileSync(f, 'utf8'))
        .filter((c) => !tokenValues.has(c.toLowerCase().replace(/\s+/g, '')))
        .map((c) => `${relative(SRC, f)}: ${c}`),
    );
    expect(strays).toEqual([]);
  });

  it('only read custom properties the tokens set or the sheets define', () => {
    const defined = new Set(Object.keys(cssVariables()));
    const texts = sheets.map((f) => readFileSync(f, 'utf8'));
    for (const t of texts) for (const m of t.matchAll(/(--[\w-]+)\s*:/g)) defined.add(m[1]);
    const undefinedVars = texts.flatMap((t) => [...t.matchAll(/var\(\s*(--[\w-]+)/g)].map((m) => m[1]));
    expect([...new Set(undefinedVars.filter((v) => !defined.has(v)))]).toEqual([]);
  });

  it('leave no token variable unused', () => {
    const all = sheets.map((f) => readFileSync(f, 'utf8')).join('\n');
    const unused = Object.keys(cssVariables()).filter((v) => !all.includes(`var(${v})`));
    // The link colours are there for components that colour a legend or a swatch in CSS.
    expect(unused.filter((v) => !['--crank', '--coupler', '--rocker', '--trace'].includes(v))).toEqual([]);
  });
});

describe('canvas renderer source', () => {
  it('names no colour of its own: every colour comes through shared/canvas/canvasTheme.ts from the tokens', () => {
    const sources = [
      ...filesUnder(join(SRC, 'shared/canvas'), '.ts'),
      ...filesUnder(join(SRC, 'shared/linkage'), '.ts'),
    ];
    expect(sources.length).toBeGreaterThan(10);
    const strays = sources.flatMap((f) =>
      [...readFileSync(f, 'utf8').matchAll(/['"`](#[0-9a-f]{3,8}|rgba?\([^)]*\))['"`]/gi)].map(
        (m) => `${relative(SRC, f)}: ${m[1]}`,
      ),
    );
    expect(strays).toEqual([]);
  });
});

describe('applyTokens', () => {
  it('sets every token variable, with the token value', () => {
    const set = new Map<string, string>();
    applyTokens({ setProperty: (name, value) => void set.set(name, value) });
    expect(Object.fromEntries(set)).toEqual(cssVariables());
    expect(set.get('--bg')).toBe(COLORS.pageBackground);
    expect(set.get('--coupler')).toBe(COLORS.coupler);
  });
});
