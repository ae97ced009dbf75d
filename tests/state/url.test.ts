import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { AppState } from '../../src/state/appState';
import { LAB_STEPS_DEG, LAB_TOLERANCES } from '../../src/lab/options';
import { SWEEP_METHODS } from '../../src/solver/methods';
import { DEFAULT_STATE } from '../../src/state/appState';
import { DEFAULT_EMBED, appUrl, embedCode, embedUrl, parseUrl, serializeState } from '../../src/state/url';

const quiet = () => undefined;

describe('serializeState and parseUrl', () => {
  it('round-trips the default state exactly', () => {
    const q = serializeState(DEFAULT_STATE);
    expect(parseUrl(q, DEFAULT_STATE, quiet).state).toEqual(DEFAULT_STATE);
  });

  it('round-trips any valid state exactly (seeded property test)', () => {
    const length = fc.double({ min: 1e-9, max: 1e9, noNaN: true, noDefaultInfinity: true });
    const state: fc.Arbitrary<AppState> = fc.record({
      linkage: fc.record({ r1: length, r2: length, r3: length, r4: length }),
      theta2Deg: fc.double({ min: 0, max: 360, maxExcluded: true, noNaN: true }),
      branch: fc.constantFrom('open' as const, 'crossed' as const),
      coupler: fc.record({
        distance: fc.double({ min: 0, max: 1e9, noNaN: true, noDefaultInfinity: true }),
        angleDeg: fc.double({ min: -180, max: 180, minExcluded: true, noNaN: true }),
      }),
      playing: fc.boolean(),
      speedDegPerFrame: fc.double({ min: 0.5, max: 10, noNaN: true }),
      direction: fc.constantFrom(1 as const, -1 as const),
      showGrid: fc.boolean(),
      showAngles: fc.boolean(),
      showGhost: fc.boolean(),
      showTrace: fc.boolean(),
      nrStart: fc.constantFrom('continuation' as const, 'cold' as const),
      plotLayout: fc.constantFrom('separate' as const, 'together' as const),
      samples: fc.integer({ min: 12, max: 36000 }),
      locale: fc.constantFrom('en' as const, 'zh-TW' as const),
      view: fc.record({
        zoom: fc.double({ min: 0.001, max: 1000, noNaN: true }),
        panX: fc.double({ min: -100, max: 100, noNaN: true }),
        panY: fc.double({ min: -100, max: 100, noNaN: true }),
      }),
      method: fc.constantFrom(...SWEEP_METHODS),
      tol: fc.constantFrom(null, ...LAB_TOLERANCES),
      page: fc.constantFrom('simulator' as const, 'lab' as const),
      labStepDeg: fc.constantFrom(...LAB_STEPS_DEG),
    });
    fc.assert(
      fc.property(state, (s) => {
        // -0 and 0 serialise alike; the state never needs to tell them apart.
        const clean = JSON.parse(JSON.stringify(s)) as AppState;
        const back = parseUrl(serializeState(clean), DEFAULT_STATE, quiet);
        expect(back.warnings).toEqual([]);
        expect(JSON.parse(JSON.stringify(back.state))).toEqual(clean);
      }),
      { seed: 20251222, numRuns: 300 },
    );
  });

  it('rejects an unknown method, tolerance or page with a warning', () => {
    const warnings: string[] = [];
    const r = parseUrl('m=bisection&tol=1e-7&page=debug&lstep=2', DEFAULT_STATE, (m) => warnings.push(m));
    expect(r.state.method).toBe(DEFAULT_STATE.method);
    expect(r.state.tol).toBe(DEFAULT_STATE.tol);
    expect(r.state.page).toBe('simulator');
    expect(r.state.labStepDeg).toBe(1);
    expect(warnings).toHaveLength(4);
    expect(warnings[0]).toContain('m="bisection"');
  });

  it('keeps lengths like 2.000000001 exactly', () => {
    const s = { ...DEFAULT_STATE, linkage: { r1: 4, r2: 1, r3: 3, r4: 2.000000001 } };
    expect(parseUrl(serializeState(s), DEFAULT_STATE, quiet).state.linkage.r4).toBe(2.000000001);
  });

  it('ignores each bad parameter with a warning and keeps the default', () => {
    const warnings: string[] = [];
    const r = parseUrl(
      '?r1=abc&r2=-1&r3=0&r4=1e308&t2=NaN&br=sideways&n=7&lang=fr&spd=99&z=0&grid=maybe&bogus=1',
      DEFAULT_STATE,
      (m) => warnings.push(m),
    );
    expect(r.state).toEqual(DEFAULT_STATE);
    expect(warnings).toHaveLength(12);
    expect(warnings[0]).toContain('r1="abc"');
    expect(warnings.join('\n')).toContain('bogus');
  });

  it('takes a partial URL on top of the base state', () => {
    const r = parseUrl('r2=2.5&t2=-30&br=crossed&lang=zh-TW', DEFAULT_STATE, quiet);
    expect(r.state.linkage).toEqual({ r1: 6, r2: 2.5, r3: 5, r4: 5 });
    expect(r.state.theta2Deg).toBe(330);
    expect(r.state.branch).toBe('crossed');
    expect(r.state.locale).toBe('zh-TW');
  });

  it('parses embed panels and locks, and rejects unknown names', () => {
    expect(parseUrl('panels=controls,info&lock=r1,r2,theta2', DEFAULT_STATE, quiet).embed).toEqual({
      panels: ['controls', 'info'],
      locked: ['r1', 'r2', 'theta2'],
    });
    expect(parseUrl('panels=none', DEFAULT_STATE, quiet).embed.panels).toEqual([]);
    const bad = parseUrl('panels=controls,evil&lock=everything', DEFAULT_STATE, quiet);
    expect(bad.embed).toEqual(DEFAULT_EMBED);
    expect(bad.warnings).toHaveLength(2);
  });

  it('round-trips embed options', () => {
    const embed = { panels: ['info' as const, 'plots' as const], locked: ['r1' as const, 'branch' as const] };
    expect(parseUrl(serializeState(DEFAULT_STATE, embed), DEFAULT_STATE, quiet).embed).toEqual(embed);
  });

  it('accepts the sample-count option n=3600', () => {
    expect(parseUrl('n=3600', DEFAULT_STATE, quiet).state.samples).toBe(3600);
    expect(parseUrl('n=3600.5', DEFAULT_STATE, quiet).state.samples).toBe(360);
  });
});

describe('embedUrl, appUrl and embedCode', () => {
  it('points the embed at embed.html beside the app page', () => {
    const u = embedUrl('https://example.edu/course/fourbar/index.html?r1=1#x', DEFAULT_STATE, DEFAULT_EMBED);
    expect(u.startsWith('https://example.edu/course/fourbar/embed.html?r1=6&')).toBe(true);
    expect(u).toContain('panels=controls%2Cplots');
    expect(appUrl('https://example.edu/course/fourbar/embed.html?x=1', DEFAULT_STATE)).toMatch(
      /^https:\/\/example\.edu\/course\/fourbar\/\?r1=6&/,
    );
  });
  it('escapes the URL and title in the iframe snippet and sandboxes it', () => {
    const code = embedCode('https://a.b/embed.html?x=1&y="2"', 'A <b> "title"');
    expect(code).toContain('src="https://a.b/embed.html?x=1&amp;y=&quot;2&quot;"');
    expect(code).toContain('title="A &lt;b&gt; &quot;title&quot;"');
    expect(code).toContain('sandbox="allow-scripts');
  });
});
