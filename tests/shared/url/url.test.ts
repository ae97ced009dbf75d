import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import { DEFAULT_EMBED, appUrl, embedUrl, parseUrl, serializeState } from '../../../src/shared/url/url';
import { DEFAULT_TARGET, URL_KEYS, urlKeysOn } from '../../../src/shared/url/urlKeys';
import type { Page } from '../../../src/shared/state/appState';
import { PAGE_URL_VALUES } from '../../../src/shared/state/slices/shellSlice';
import type { FlatState } from '../state/stateFixtures';
import { withFields } from '../state/stateFixtures';
import { anyLinkState, oneSliceState } from '../state/sliceArbitraries';
import { SLICE_NAMES } from '../../../src/shared/state/appState';

const quiet = () => undefined;
const SEED = 20251222;

/** -0 and 0 serialise alike; the state never needs to tell them apart. */
function withoutNegativeZero<T>(x: T): T {
  return JSON.parse(JSON.stringify(x)) as T;
}

/** Circular distance between two angles in degrees. */
function angleGapDeg(a: number, b: number): number {
  const d = Math.abs(a - b) % 360;
  return Math.min(d, 360 - d);
}

describe('serializeState and parseUrl', () => {
  it('round-trips the default state exactly', () => {
    const q = serializeState(DEFAULT_STATE);
    const r = parseUrl(q, DEFAULT_STATE, quiet);
    expect(r.state).toEqual(DEFAULT_STATE);
    expect(r.ignored).toEqual([]);
  });

  it('round-trips any valid state on the URL grids exactly (seeded property)', () => {
    fc.assert(
      fc.property(anyLinkState, (s) => {
        const clean = withoutNegativeZero(s);
        const back = parseUrl(serializeState(clean), DEFAULT_STATE, quiet);
        expect(back.ignored).toEqual([]);
        expect(withoutNegativeZero(back.state)).toEqual(clean);
      }),
      { seed: SEED, numRuns: 300 },
    );
  });

  it.each(SLICE_NAMES)('round-trips any %s slice exactly (seeded property, every key of the slice)', (name) => {
    fc.assert(
      fc.property(oneSliceState(name), (s) => {
        const clean = withoutNegativeZero(s);
        const back = parseUrl(serializeState(clean), DEFAULT_STATE, quiet);
        expect(back.ignored).toEqual([]);
        expect(withoutNegativeZero(back.state)).toEqual(clean);
      }),
      { seed: SEED, numRuns: 100 },
    );
  });

  it('keeps an off-centre pivot box of the path task (bp) exactly', () => {
    const pivotBox = { min: { x: -30, y: 5 }, max: { x: 12.5, y: 40 } };
    const s = { ...DEFAULT_STATE, synPath: { ...DEFAULT_STATE.synPath, pivotBox } };
    const q = serializeState(s);
    expect(new URLSearchParams(q).get('bp')).toBe('-30,5,12.5,40');
    expect(parseUrl(q, DEFAULT_STATE, quiet).state.synPath.pivotBox).toEqual(pivotBox);
    expect(parseUrl('bp=-30,5,12.5,40', DEFAULT_STATE, quiet).state.synPath.pivotBox).toEqual(pivotBox);
  });

  it('writes any valid state stably: a second round trip changes nothing, angles move < 5e-10 deg (seeded property)', () => {
    const raw = fc.record({
      theta2Deg: fc.double({ min: 0, max: 360, maxExcluded: true, noNaN: true }),
      angleDeg: fc.double({ min: -180, max: 180, minExcluded: true, noNaN: true }),
      zoom: fc.double({ min: 0.0011, max: 999, noNaN: true }),
      panX: fc.double({ min: -99, max: 99, noNaN: true }),
    });
    fc.assert(
      fc.property(raw, ({ theta2Deg, angleDeg, zoom, panX }) => {
        const s = withFields(DEFAULT_STATE, {
          theta2Deg,
          coupler: { ...DEFAULT_STATE.design.coupler, angleDeg },
          view: { zoom, panX, panY: 0 },
        });
        const q = serializeState(s);
        const back = parseUrl(q, DEFAULT_STATE, quiet).state;
        expect(serializeState(back)).toBe(q);
        // Rounding to 9 decimals moves an angle by at most half a unit in the last place, 5e-10 deg.
        expect(angleGapDeg(back.motion.theta2Deg, theta2Deg)).toBeLessThanOrEqual(5e-10 + 1e-12);
        expect(angleGapDeg(back.design.coupler.angleDeg, angleDeg)).toBeLessThanOrEqual(5e-10 + 1e-12);
        expect(back.motion.theta2Deg).toBeGreaterThanOrEqual(0);
        expect(back.motion.theta2Deg).toBeLessThan(360);
        // Six significant digits: relative change at most 5e-6.
        expect(Math.abs(back.display.view.zoom - zoom)).toBeLessThanOrEqual(5e-6 * zoom);
      }),
      { seed: SEED, numRuns: 300 },
    );
  });

  it('has a codec per key that reads back its own text for the default target', () => {
    // Names are unique within a page's table; a page's own keys (the spatial page's r2) shadow the others'.
    for (const page of Object.keys(PAGE_URL_VALUES) as Page[]) {
      const names = urlKeysOn(page).map((k) => k.name);
      expect(new Set(names).size, page).toBe(names.length);
    }
    for (const k of URL_KEYS) {
      const v = k.get(DEFAULT_TARGET);
      const r = k.parse(k.format(v));
      expect(r, k.name).toEqual({ ok: true, value: v });
    }
  });

  it('writes the optional keys only when they differ from the default', () => {
    const plain = new URLSearchParams(serializeState(DEFAULT_STATE));
    for (const k of ['page', 'lstep', 'w2', 'a2', 'mulo', 'muhi', 'z', 'px', 'py', 'panels', 'lock'])
      expect(plain.has(k), k).toBe(false);
    const s = withFields(DEFAULT_STATE, {
      page: 'lab',
      labStepDeg: 5,
      omega2RadPerS: -2.5,
      alpha2RadPerS2: 3,
      muBandLoDeg: 30,
      muBandHiDeg: 150,
      view: { zoom: 1, panX: 0.25, panY: 0 },
    });
    const q = new URLSearchParams(serializeState(s));
    expect(Object.fromEntries(q)).toMatchObject({
      page: 'lab',
      lstep: '5',
      w2: '-2.5',
      a2: '3',
      mulo: '30',
      muhi: '150',
      z: '1',
      px: '0.25',
      py: '0',
    });
  });

  it('writes numbers compactly: t2 from Play without float noise, lengths exactly, the view to six digits', () => {
    const s = withFields(DEFAULT_STATE, {
      linkage: { r1: 4, r2: 1, r3: 3, r4: 2.000000001 },
      theta2Deg: 248.98895999999954,
      coupler: { distance: 0.1 + 0.2, angleDeg: -20.000000000000004 },
      view: { zoom: 1.1 * 1.1, panX: -0.1 - 0.2, panY: 0 },
    });
    const q = new URLSearchParams(serializeState(s));
    expect(q.get('t2')).toBe('248.98896');
    expect(q.get('r4')).toBe('2.000000001');
    expect(q.get('pd')).toBe('0.30000000000000004');
    expect(q.get('pa')).toBe('-20');
    expect(q.get('z')).toBe('1.21');
    expect(q.get('px')).toBe('-0.3');
    expect(appUrl('https://example.edu/embed.html', s)).toContain('t2=248.98896&');
  });

  it('writes an angle that rounds up to 360 as 0', () => {
    const s = withFields(DEFAULT_STATE, { theta2Deg: 359.9999999999 });
    expect(new URLSearchParams(serializeState(s)).get('t2')).toBe('0');
    expect(parseUrl(serializeState(s), DEFAULT_STATE, quiet).state.motion.theta2Deg).toBe(0);
  });

  it('keeps lengths like 2.000000001 exactly', () => {
    const s = withFields(DEFAULT_STATE, { linkage: { r1: 4, r2: 1, r3: 3, r4: 2.000000001 } });
    expect(parseUrl(serializeState(s), DEFAULT_STATE, quiet).state.design.linkage.r4).toBe(2.000000001);
  });

  it('takes a partial URL on top of the base state', () => {
    const r = parseUrl('r2=2.5&t2=-30&br=crossed&lang=zh-TW&pa=270', DEFAULT_STATE, quiet);
    expect(r.state.design.linkage).toEqual({ r1: 6, r2: 2.5, r3: 5, r4: 5 });
    expect(r.state.motion.theta2Deg).toBe(330);
    expect(r.state.design.coupler.angleDeg).toBe(-90);
    expect(r.state.design.branch).toBe('crossed');
    expect(r.state.shell.locale).toBe('zh-TW');
  });

  it('reads the input motion and the transmission band', () => {
    const r = parseUrl('w2=-3.5&a2=12&mulo=30&muhi=150', DEFAULT_STATE, quiet);
    expect(r.state).toEqual(
      withFields(DEFAULT_STATE, { omega2RadPerS: -3.5, alpha2RadPerS2: 12, muBandLoDeg: 30, muBandHiDeg: 150 }),
    );
    expect(r.ignored).toEqual([]);
  });

  it('parses embed panels and locks, and rejects unknown names', () => {
    expect(parseUrl('panels=controls,info&lock=r1,r2,theta2', DEFAULT_STATE, quiet).embed).toEqual({
      panels: ['controls', 'info'],
      locked: ['r1', 'r2', 'theta2'],
    });
    expect(parseUrl('panels=none', DEFAULT_STATE, quiet).embed.panels).toEqual([]);
    const bad = parseUrl('panels=controls,evil&lock=everything', DEFAULT_STATE, quiet);
    expect(bad.embed).toEqual(DEFAULT_EMBED);
    expect(bad.ignored.map((p) => p.key)).toEqual(['panels', 'lock']);
  });

  it('round-trips embed options', () => {
    const embed = { panels: ['info' as const, 'plots' as const], locked: ['r1' as const, 'branch' as const] };
    expect(parseUrl(serializeState(DEFAULT_STATE, embed), DEFAULT_STATE, quiet).embed).toEqual(embed);
    const none = { panels: [], locked: [] };
    expect(parseUrl(serializeState(DEFAULT_STATE, none), DEFAULT_STATE, quiet).embed).toEqual(none);
  });

  it('accepts the sample-count option n=3600', () => {
    expect(parseUrl('n=3600', DEFAULT_STATE, quiet).state.solver.samples).toBe(3600);
    expect(parseUrl('n=3600.5', DEFAULT_STATE, quiet).state.solver.samples).toBe(360);
  });
});

/** Every range check of the URL: [key, text, accepted?]; a rejected text leaves the default and is reported. */
const RANGE_CASES: ReadonlyArray<readonly [key: string, text: string, accepted: boolean]> = [
  ['r1', '1e-300', true],
  ['r1', '1e300', true],
  ['r1', '0', false],
  ['r1', '-1', false],
  ['r1', '1e-301', false],
  ['r1', '1e308', false],
  ['r1', 'Infinity', false],
  ['r1', '0x10', false],
  ['r1', 'abc', false],
  ['r2', '0', false],
  ['r3', 'abc', false],
  ['r4', '-2', false],
  ['t2', '-1000000', true],
  ['t2', '1000000', true],
  ['t2', '1000001', false],
  ['t2', '-1000001', false],
  ['t2', 'NaN', false],
  ['pd', '0', true],
  ['pd', '-0.5', false],
  ['pa', '1000000', true],
  ['pa', '-1000001', false],
  ['spd', '0.5', true],
  ['spd', '10', true],
  ['spd', '0,75', true],
  ['spd', '0.49', false],
  ['spd', '10.01', false],
  ['n', '12', true],
  ['n', '36000', true],
  ['n', '11', false],
  ['n', '36001', false],
  ['n', '12.5', false],
  ['z', '0.001', true],
  ['z', '1000', true],
  ['z', '0.00099', false],
  ['z', '1000.1', false],
  ['z', '0', false],
  ['px', '100', true],
  ['px', '-100', true],
  ['px', '100.001', false],
  ['px', '-100.001', false],
  ['py', '100', true],
  ['py', '-100.5', false],
  ['w2', '-1000000', true],
  ['w2', '1000000', true],
  ['w2', '1000001', false],
  ['w2', '-1e7', false],
  ['a2', '1e9', true],
  ['a2', '-1.1e9', false],
  ['w2u', 'rpm', true],
  ['w2u', 'RPM', false],
  ['mulo', '0', true],
  ['mulo', '-1', false],
  ['mulo', '181', false],
  ['muhi', '180', true],
  ['muhi', '180.5', false],
  ['lstep', '5', true],
  ['lstep', '2', false],
  ['tol', '1e-9', true],
  ['tol', 'default', true],
  ['tol', '1e-7', false],
  ['br', 'crossed', true],
  ['br', 'Crossed', false],
  ['dir', 'cw', true],
  ['dir', 'left', false],
  ['grid', 'maybe', false],
  ['dc', 'maybe', false],
  ['dc', '1', true],
  ['ic', 'maybe', false],
  ['ic', '0', true],
  ['vel', '1', true],
  ['vel', 'maybe', false],
  ['acc', 'on', true],
  ['acc', '2', false],
  ['plot', 'vel', true],
  ['plot', 'acc', true],
  ['plot', 'jerk', false],
  ['nr', 'warm', false],
  ['plots', 'stacked', false],
  ['lang', 'ZH-tw', true],
  ['lang', 'fr', false],
  ['m', 'bisection', false],
  ['page', 'debug', false],
  ['page', 'syn', true],
  ['ox', '-2.5', true],
  ['ox', 'abc', false],
  ['oy', '1e9', true],
  ['oy', '1.1e9', false],
  ['og', '-90', true],
  ['og', '400', false],
  ['syn', 'fn', true],
  ['syn', 'function', true],
  ['syn', 'func', false],
  ['tg', '1,2;3,4.5;-1e-3,0', true],
  ['tg', '1,2;3', false],
  ['tm', 'step', true],
  ['tm', 'timed', false],
  ['ts', '-15', true],
  ['ts', '0', false],
  ['tt', '0,30,60', true],
  ['tt', '0,x', false],
  ['bl', '12', true],
  ['bl', '-1', false],
  ['bc', 'auto', true],
  ['bc', '0', false],
  ['bp', '-5,-5,5,5', true],
  ['bp', '5,-5,-5,5', false],
  ['in', 'any', true],
  ['in', 'rocker', false],
  ['sd', '7', true],
  ['sd', '0', false],
  ['cd', '2', true],
  ['cd', '-1', false],
  ['ps', '0,0,0;1,2,45', true],
  ['ps', '0,0,0', false],
  ['pc', 'fixed', true],
  ['pc', 'both', false],
  ['pv', '0,1;2,3', true],
  ['pv', '0,1', false],
  ['dy', '1,2', true],
  ['dy', '1,2;3,4;5,6', false],
  ['mc', '3', true],
  ['mc', '15', false],
  ['mg', 'auto', true],
  ['mg', '0', false],
  ['mq', '1.5', true],
  ['mq', '0.9', false],
  ['fx', 'sin(x) + 1', true],
  ['fx', 'alert("x")', false],
  ['xr', '-1,1', true],
  ['xr', '1,1', false],
  ['t2r', '0,180', true],
  ['t2r', '0,720', false],
  ['t4r', '90,-90', true],
  ['t4r', '0', false],
  ['np', '7', true],
  ['np', '2', false],
  ['tpl', 'jansen', true],
  ['tpl', 'slider-crank', true],
  ['tpl', 'sliderCrank', false],
  ['mech', 'm1*2*ground*crank*1*O2*R*0*1*0*0*0*0', true],
  ['mech', 'm1*2*ground*crank*1*O2*Q*0*1*0*0*0*0', false],
  ['mech', 'm1*1*ground*0*0*-1', true],
  [
    'mech',
    '{"links":["ground","a"],"joints":[{"id":"O","kind":"R","links":["ground","a"],"x":0,"y":0}],"input":{"joint":"O"}}',
    true,
  ],
  ['mech', '{"links":["ground"],"joints":[],"input":{"joint":"X"}}', false],
  ['mfrc', '1', true],
  ['mfrc', 'yes please', false],
  ['mrho', '2.5', true],
  ['mrho', '-1', false],
  ['mgr', '0', true],
  ['mgr', '1001', false],
  ['mw', '-30', true],
  ['mw', '2e6', false],
  ['mrj', 'B', true],
  ['mrj', 'x'.repeat(201), false],
  ['mfv', '1', true],
  ['mfv', '2', false],
  ['mi', '-0.5', true],
  ['mi', 'abc', false],
  ['mdir', 'rev', true],
  ['mdir', 'back', false],
  ['mspd', '120', true],
  ['mspd', '0', false],
  ['mtr', '2*P*Foot', true],
  ['mtr', '3*P', false],
  ['mp', '2*angle%3Acrank*', true],
  ['mp', '1*angle%3Acrank', false],
  ['mvel', '1', true],
  ['mvel', 'on and off', false],
  ['frc', '1', true],
  ['frc', 'maybe', false],
  ['lu', 'mm', true],
  ['lu', 'km', false],
  ['mass', 'link', true],
  ['mass', 'heavy', false],
  ['rho', '2.5', true],
  ['rho', '-1', false],
  ['m2', '1.5', true],
  ['m2', '-1', false],
  ['i2', '0.01', true],
  ['i2', '-0.01', false],
  ['c2', '0.5', true],
  ['c2', '1e10', false],
  ['ca2', '30', true],
  ['ca2', 'abc', false],
  ['m3', '1.5', true],
  ['m3', '-1', false],
  ['i3', '0.01', true],
  ['i3', '-0.01', false],
  ['c3', '0.5', true],
  ['c3', '1e10', false],
  ['ca3', '30', true],
  ['ca3', 'abc', false],
  ['m4', '1.5', true],
  ['m4', '-1', false],
  ['i4', '0.01', true],
  ['i4', '-0.01', false],
  ['c4', '0.5', true],
  ['c4', '1e10', false],
  ['ca4', '30', true],
  ['ca4', 'abc', false],
  ['g', '0', true],
  ['g', '-9.81', false],
  ['gd', '-90', true],
  ['gd', 'down', false],
  ['pfx', '-100', true],
  ['pfx', '1e10', false],
  ['pfy', '50', true],
  ['pfy', 'abc', false],
  ['tl', '-3', true],
  ['tl', '1e10', false],
  ['fv', '1', true],
  ['fv', 'maybe', false],
  ['cs', '0.02', true],
  ['cs', '0', false],
];

/** The spatial page's keys, read only on page=3d (where r2, r3, r4, t2, br, pd, pa and a2 are its own). */
const SPATIAL_RANGE_CASES: [string, string, boolean][] = [
  ['sk', 'rssr', true],
  ['sk', 'cone', false],
  ['a1', '60', true],
  ['a1', '180', false],
  ['a2', '0.5', true],
  ['a2', '0', false],
  ['a3', '179.9', true],
  ['a3', '-5', false],
  ['a4', '45', true],
  ['a4', 'abc', false],
  ['pd', '0', true],
  ['pd', '180', false],
  ['pa', '-90', true],
  ['pa', 'x', false],
  ['r2', '1e-200', true],
  ['r2', '0', false],
  ['r3', '4', true],
  ['r3', '-4', false],
  ['r4', '2', true],
  ['r4', '1e301', false],
  ['a', '0', true],
  ['a', '-1', false],
  ['beta', '270', true],
  ['beta', 'inf', false],
  ['h2', '-3', true],
  ['h2', 'abc', false],
  ['h4', '1e300', true],
  ['h4', '2e300', false],
  ['t2', '400', true],
  ['t2', 'x', false],
  ['br', 'crossed', true],
  ['br', 'up', false],
  ['w2', '-2.5', true],
  ['w2', '1000001', false],
  ['al2', '-1e9', true],
  ['al2', 'fast', false],
];

describe('parseUrl range checks', () => {
  it.each(RANGE_CASES)('%s=%s is accepted: %s', (key, text, accepted) => {
    const r = parseUrl(`${key}=${encodeURIComponent(text)}`, DEFAULT_STATE, quiet);
    if (accepted) {
      expect(r.ignored).toEqual([]);
      const k = URL_KEYS.find((x) => x.name === key)!;
      const d = k.parse(text);
      expect(d.ok).toBe(true);
      if (d.ok) expect(k.get({ state: r.state, embed: r.embed })).toEqual(d.value);
    } else {
      expect(r.ignored.map((p) => [p.key, p.value])).toEqual([[key, text]]);
      expect(r.state).toEqual(DEFAULT_STATE);
      expect(r.embed).toEqual(DEFAULT_EMBED);
    }
  });

  it.each(SPATIAL_RANGE_CASES)('page=3d&%s=%s is accepted: %s', (key, text, accepted) => {
    const r = parseUrl(`page=3d&${key}=${encodeURIComponent(text)}`, DEFAULT_STATE, quiet);
    const onPage = { ...DEFAULT_STATE, shell: { ...DEFAULT_STATE.shell, page: 'spatial' as const } };
    if (accepted) {
      expect(r.ignored).toEqual([]);
      const k = urlKeysOn('spatial').find((x) => x.name === key)!;
      expect(k.page).toBe('spatial');
      const d = k.parse(text);
      expect(d.ok).toBe(true);
      if (d.ok) expect(k.get({ state: r.state, embed: r.embed })).toEqual(d.value);
      // The simulator's values of the same names are untouched.
      expect(r.state.design).toBe(DEFAULT_STATE.design);
      expect(r.state.motion).toBe(DEFAULT_STATE.motion);
    } else {
      expect(r.ignored.map((p) => [p.key, p.value])).toEqual([[key, text]]);
      expect(r.state).toEqual(onPage);
    }
  });

  it('tests a rejected and an accepted value of every key', () => {
    for (const k of URL_KEYS.filter((x) => !['panels', 'lock', 'play', 'ang', 'ghost', 'trace'].includes(x.name))) {
      const cases = k.page === 'spatial' ? SPATIAL_RANGE_CASES : RANGE_CASES;
      expect(
        cases.some(([key, , ok]) => key === k.name && !ok),
        k.name,
      ).toBe(true);
    }
  });

  it("reads the spatial page's keys only on page=3d, and the simulator's of the same names elsewhere", () => {
    const sim = parseUrl('r2=3&a1=70&t2=10', DEFAULT_STATE, quiet);
    expect(sim.state.design.linkage.r2).toBe(3);
    expect(sim.state.motion.theta2Deg).toBe(10);
    expect(sim.state.spatial).toBe(DEFAULT_STATE.spatial);
    expect(sim.ignored.map((p) => [p.key, p.why])).toEqual([['a1', 'read only on page=3d']]);
    const spatial = parseUrl('r2=3&page=3d&a1=70&t2=10', DEFAULT_STATE, quiet);
    expect(spatial.ignored).toEqual([]);
    expect(spatial.state.spatial).toMatchObject({ r2: 3, a1Deg: 70, theta2Deg: 10 });
    expect(spatial.state.design).toBe(DEFAULT_STATE.design);
    expect(spatial.state.motion).toBe(DEFAULT_STATE.motion);
  });

  it("writes a page=3d link with the language, the page and the spatial keys only (the shown kind's always)", () => {
    const s = {
      ...DEFAULT_STATE,
      shell: { ...DEFAULT_STATE.shell, page: 'spatial' as const },
      spatial: { ...DEFAULT_STATE.spatial, kind: 'rssr' as const, a3Deg: 50 },
    };
    const q = Object.fromEntries(new URLSearchParams(serializeState(s)));
    expect(q).toMatchObject({ page: '3d', sk: 'rssr', r2: '1', r3: '4', r4: '2', a: '3', beta: '60', a3: '50' });
    expect(q).not.toHaveProperty('a1');
    expect(q).not.toHaveProperty('r1');
    expect(q).not.toHaveProperty('play');
    expect(parseUrl(serializeState(s), DEFAULT_STATE, quiet).state).toEqual(s);
  });

  it('refuses a transmission band whose edges cross, reverting the keys that broke it', () => {
    const both = parseUrl('mulo=100&muhi=60', DEFAULT_STATE, quiet);
    expect([both.state.display.muBandLoDeg, both.state.display.muBandHiDeg]).toEqual([40, 140]);
    expect(both.ignored.map((p) => [p.key, p.value])).toEqual([
      ['mulo', '100'],
      ['muhi', '60'],
    ]);
    const lo = parseUrl('mulo=150', DEFAULT_STATE, quiet);
    expect(lo.state.display.muBandLoDeg).toBe(40);
    expect(lo.ignored.map((p) => p.key)).toEqual(['mulo']);
    const equal = parseUrl('mulo=90&muhi=90', DEFAULT_STATE, quiet);
    expect(equal.ignored).toHaveLength(2);
    const fine = parseUrl('mulo=150&muhi=170', DEFAULT_STATE, quiet);
    expect([fine.state.display.muBandLoDeg, fine.state.display.muBandHiDeg]).toEqual([150, 170]);
  });
});

describe('parseUrl meanings', () => {
  it('reads each word as the state it names', () => {
    const cases: Array<[string, Partial<FlatState>]> = [
      ['br=crossed', { branch: 'crossed' }],
      ['dir=cw', { direction: -1 }],
      ['dir=ccw', { direction: 1 }],
      ['nr=cold', { nrStart: 'cold' }],
      ['nr=cont', { nrStart: 'continuation' }],
      ['plots=together', { plotLayout: 'together' }],
      ['plot=vel&vel=1&acc=1', { plotKind: 'velocities', showVelocity: true, showAcceleration: true }],
      ['plot=acc', { plotKind: 'accelerations' }],
      ['page=lab', { page: 'lab' }],
      ['lang=zh-TW', { locale: 'zh-TW' }],
      ['tol=default', { tol: null }],
      [
        'grid=0&ang=off&ghost=no&trace=false&play=yes',
        { showGrid: false, showAngles: false, showGhost: false, showTrace: false, playing: true },
      ],
      ['m=seed', { method: 'seed' }],
    ];
    for (const [q, expected] of cases)
      expect(parseUrl(q, DEFAULT_STATE, quiet).state, q).toEqual(withFields(DEFAULT_STATE, expected));
    const back = new URLSearchParams(
      serializeState(withFields(DEFAULT_STATE, { direction: -1, nrStart: 'cold', page: 'lab' })),
    );
    expect([back.get('dir'), back.get('nr'), back.get('page')]).toEqual(['cw', 'cold', 'lab']);
  });
});

describe('parseUrl ignored parameters', () => {
  it('lists each bad or unknown parameter with its raw value, in URL order, and warns once for each', () => {
    const warnings: string[] = [];
    const r = parseUrl(
      '?r1=abc&r2=-1&r3=0&r4=1e308&t2=NaN&br=sideways&n=7&lang=fr&spd=99&z=0&grid=maybe&bogus=1',
      DEFAULT_STATE,
      (m) => warnings.push(m),
    );
    expect(r.state).toEqual(DEFAULT_STATE);
    expect(r.ignored.map((p) => p.key)).toEqual([
      'r1',
      'r2',
      'r3',
      'r4',
      't2',
      'br',
      'n',
      'lang',
      'spd',
      'z',
      'grid',
      'bogus',
    ]);
    expect(r.ignored[0]).toMatchObject({ key: 'r1', value: 'abc', shownKey: 'r1', shownValue: 'abc' });
    expect(r.ignored[11].why).toBe('unknown parameter');
    expect(warnings).toEqual(r.warnings);
    expect(warnings[0]).toContain('r1="abc"');
  });

  it('shortens a 400-character value (and key) for display, keeping the raw text', () => {
    const long = '9'.repeat(400) + 'x';
    const r = parseUrl(`r3=${long}&${'k'.repeat(300)}=1`, DEFAULT_STATE, quiet);
    expect(r.ignored[0].value).toBe(long);
    expect(r.ignored[0].shownValue).toBe('9'.repeat(23) + '…');
    expect(r.ignored[1].shownKey).toBe('k'.repeat(23) + '…');
    expect(r.warnings[0].length).toBeLessThan(120);
  });

  it('keeps the last valid value of a repeated key and reports the bad one', () => {
    const r = parseUrl('r1=5&r1=oops', DEFAULT_STATE, quiet);
    expect(r.state.design.linkage.r1).toBe(5);
    expect(r.ignored.map((p) => p.value)).toEqual(['oops']);
  });
});

describe('embedUrl and appUrl', () => {
  it('points the embed at embed.html beside the app page', () => {
    const u = embedUrl('https://example.edu/course/fourbar/index.html?r1=1#x', DEFAULT_STATE, DEFAULT_EMBED);
    expect(u.startsWith('https://example.edu/course/fourbar/embed.html?r1=6&')).toBe(true);
    expect(u).toContain('panels=controls%2Cplots');
    expect(appUrl('https://example.edu/course/fourbar/embed.html?x=1', DEFAULT_STATE)).toMatch(
      /^https:\/\/example\.edu\/course\/fourbar\/\?r1=6&/,
    );
  });
});
