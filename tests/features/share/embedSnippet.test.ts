import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  DEFAULT_EMBED_PRESET,
  EMBED_PRESETS,
  EMBED_SANDBOX,
  RESPONSIVE_MIN_HEIGHT,
  embedSnippet,
  escapeAttribute,
} from '../../../src/features/share/embedSnippet';
import type { EmbedPreset } from '../../../src/features/share/embedSnippet';

// Independent oracle: a tiny reader of double-quoted attributes that undoes the five entities HTML defines
// for them. If the snippet left a raw quote or angle bracket in a value, the reader would split it wrongly.
function attributes(tag: string): Record<string, string> {
  const out: Record<string, string> = {};
  for (const m of tag.matchAll(/\s([a-z-]+)="([^"<>]*)"/g)) {
    out[m[1]] = m[2]
      .replace(/&quot;/g, '"')
      .replace(/&lt;/g, '<')
      .replace(/&gt;/g, '>')
      .replace(/&#39;/g, "'")
      .replace(/&amp;/g, '&');
  }
  return out;
}

function iframeTag(html: string): string {
  const m = /<iframe\b[^>]*>/.exec(html);
  if (!m) throw new Error(`no iframe in ${html}`);
  return m[0];
}

const preset = (id: EmbedPreset['id']): EmbedPreset => {
  const p = EMBED_PRESETS.find((x) => x.id === id);
  if (!p) throw new Error(id);
  return p;
};

describe('EMBED_PRESETS', () => {
  it('offers compact 600×450, standard 760×520 (the default), large 900×640 and a responsive frame', () => {
    expect(EMBED_PRESETS.map((p) => [p.id, p.width, p.height, p.responsive])).toEqual([
      ['compact', 600, 450, false],
      ['standard', 760, 520, false],
      ['large', 900, 640, false],
      ['responsive', 760, 520, true],
    ]);
    expect(DEFAULT_EMBED_PRESET.id).toBe('standard');
  });
});

describe('embedSnippet', () => {
  const src = 'https://example.edu/fourbar/embed.html?r1=6&r3=5&panels=controls%2Cplots';

  it('writes a fixed iframe with title, fullscreen, lazy loading, the sandbox and the preset size', () => {
    const html = embedSnippet({ src, title: 'Four-bar linkage simulator', preset: preset('compact') });
    expect(html.startsWith('<iframe ')).toBe(true);
    expect(html.endsWith('></iframe>')).toBe(true);
    expect(attributes(iframeTag(html))).toEqual({
      src,
      title: 'Four-bar linkage simulator',
      loading: 'lazy',
      allow: 'fullscreen',
      sandbox: EMBED_SANDBOX,
      width: '600',
      height: '450',
      style: 'border:0;max-width:100%',
    });
  });

  it('keeps the sandbox: scripts and downloads, never top navigation', () => {
    const sandbox = attributes(iframeTag(embedSnippet({ src, title: 't', preset: DEFAULT_EMBED_PRESET }))).sandbox;
    expect(sandbox.split(' ')).toEqual(expect.arrayContaining(['allow-scripts', 'allow-downloads']));
    expect(sandbox).not.toContain('allow-top-navigation');
  });

  it('wraps the responsive iframe in an aspect-ratio div at 100 % of it', () => {
    const html = embedSnippet({ src, title: 'Sim', preset: preset('responsive') });
    const div = /^<div style="([^"]*)">/.exec(html);
    expect(div?.[1]).toBe(
      `position:relative;width:100%;max-width:760px;aspect-ratio:760/520;min-height:${RESPONSIVE_MIN_HEIGHT}px`,
    );
    expect(html.trimEnd().endsWith('</iframe>\n</div>')).toBe(true);
    const a = attributes(iframeTag(html));
    expect(a.style).toBe('position:absolute;inset:0;width:100%;height:100%;border:0');
    expect(a.width).toBeUndefined();
    expect([a.src, a.title, a.loading, a.allow, a.sandbox]).toEqual([src, 'Sim', 'lazy', 'fullscreen', EMBED_SANDBOX]);
  });

  it('escapes any src and title so they read back unchanged and cannot close the attribute or the tag', () => {
    fc.assert(
      fc.property(fc.string({ unit: 'binary' }), fc.string({ unit: 'binary' }), (s, title) => {
        for (const p of EMBED_PRESETS) {
          const html = embedSnippet({ src: s, title, preset: p });
          const tag = iframeTag(html);
          const a = attributes(tag);
          expect([a.src, a.title]).toEqual([s, title]);
          // One tag start per element: nothing in a value opened a new tag.
          expect(html.split('<').length - 1).toBe(p.responsive ? 4 : 2);
        }
      }),
      { seed: 12, numRuns: 100 },
    );
  });

  it('escapes the five characters that matter in a quoted attribute', () => {
    expect(escapeAttribute(`a&b"c<d>e'`)).toBe('a&amp;b&quot;c&lt;d&gt;e&#39;');
  });

  it('throws for a size that is not a positive whole number, naming it', () => {
    expect(() => embedSnippet({ src, title: 't', preset: { ...DEFAULT_EMBED_PRESET, width: 0 } })).toThrow(
      'width must be a positive whole number of pixels, got 0',
    );
    expect(() => embedSnippet({ src, title: 't', preset: { ...DEFAULT_EMBED_PRESET, height: 1.5 } })).toThrow(
      /height.*1\.5/,
    );
  });
});
