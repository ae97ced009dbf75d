import { describe, expect, it } from 'vitest';
import { applyPatch } from '../../../src/features/share/embedMessages';
import { MECHANISM_TEMPLATES } from '../../../src/mechanism';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import {
  EMBED_PAGES,
  PAGE_EMBEDS,
  embedUrl,
  pageEmbedOptions,
  parseUrl,
  serializeState,
} from '../../../src/shared/url/url';

const quiet = () => undefined;

describe('PAGE_EMBEDS', () => {
  it('lists the simulator, the mechanism and the spatial page as the pages that embed', () => {
    expect(EMBED_PAGES).toEqual(['simulator', 'mechanism', 'spatial']);
  });

  it('offers only locks each page can apply', () => {
    expect(PAGE_EMBEDS.mechanism.locks).toEqual(['template', 'edit']);
    expect(PAGE_EMBEDS.spatial.locks).toEqual(['params', 'theta2', 'branch', 'play']);
  });

  it('guards the spatial input’s ω2 and α2 (w2, al2) with the params lock', () => {
    expect(pageEmbedOptions('spatial').keyLocks.w2).toBe('params');
    expect(pageEmbedOptions('spatial').keyLocks.al2).toBe('params');
  });
});

describe('embedUrl with a page’s pinned keys', () => {
  it('writes page=mech’s template even at its default, so the embed keeps its linkage', () => {
    const state = parseUrl('page=mech', DEFAULT_STATE, quiet).state;
    const q = new URL(embedUrl('https://x.test/lab/', state, { panels: ['plots'], locked: ['edit'] })).searchParams;
    expect(q.get('page')).toBe('mech');
    expect(q.get('tpl')).toBe('slider-crank');
    expect(q.get('lock')).toBe('edit');
    expect(parseUrl(q.toString(), DEFAULT_STATE, quiet).state.mech.template).toBe('sliderCrank');
  });
});

describe('parseUrl with a page’s embed options', () => {
  it('keeps the locks the page offers and refuses the others, naming them and the page', () => {
    const r = parseUrl('page=mech&tpl=jansen&lock=edit,r1', DEFAULT_STATE, quiet);
    expect(r.state.mech.template).toBe('jansen');
    expect(r.embed.locked).toEqual(['edit']);
    expect(r.ignored).toHaveLength(1);
    expect(r.ignored[0].key).toBe('lock');
    expect(r.ignored[0].why).toContain('r1 not on page=mech');
  });

  it('refuses a panel the spatial page does not show (export)', () => {
    const r = parseUrl('page=3d&panels=controls,export', DEFAULT_STATE, quiet);
    expect(r.embed.panels).toEqual(['controls']);
    expect(r.ignored[0].why).toContain('export not on page=3d');
  });

  it('round-trips a spatial embed’s keys and locks', () => {
    const r = parseUrl('page=3d&sk=rssr&r2=1.5&lock=params,theta2', DEFAULT_STATE, quiet);
    const again = parseUrl(serializeState(r.state, r.embed), DEFAULT_STATE, quiet);
    expect(again.state.spatial.r2).toBe(1.5);
    expect(again.state.spatial.kind).toBe('rssr');
    expect(again.embed.locked).toEqual(['params', 'theta2']);
  });
});

describe('applyPatch on a page’s keys', () => {
  const spatial = parseUrl('page=3d&sk=rssr', DEFAULT_STATE, quiet).state;

  it('sets the spatial page’s r2 (the RSSR crank), not the simulator’s', () => {
    const r = applyPatch(spatial, { r2: 1.25 });
    expect(r.applied).toEqual(['r2']);
    expect(r.state.spatial.r2).toBe(1.25);
    expect(r.state.design.linkage.r2).toBe(DEFAULT_STATE.design.linkage.r2);
  });

  it('refuses a spatial parameter under lock=params and θ2 under lock=theta2', () => {
    const r = applyPatch(spatial, { r2: 1.25, beta: 30, t2: 10 }, ['params', 'theta2']);
    expect(r.applied).toEqual([]);
    expect(r.refused.map((x) => x.why)).toEqual(['locked (params)', 'locked (params)', 'locked (theta2)']);
  });

  it('refuses the mechanism’s template under lock=template', () => {
    const mech = parseUrl('page=mech', DEFAULT_STATE, quiet).state;
    expect(applyPatch(mech, { tpl: 'jansen' }, ['template']).refused[0].why).toBe('locked (template)');
    expect(applyPatch(mech, { tpl: 'jansen' }).state.mech.template).toBe('jansen');
  });

  it('opens another template afresh: a host’s tpl clears the edited linkage, as the gallery does', () => {
    const edited = parseUrl('page=mech&tpl=jansen', DEFAULT_STATE, quiet).state;
    const withSpec = { ...edited, mech: { ...edited.mech, spec: MECHANISM_TEMPLATES.fourBar.spec } };
    expect(applyPatch(withSpec, { tpl: 'four-bar' }).state.mech).toMatchObject({ template: 'fourBar', spec: null });
    expect(applyPatch(withSpec, { tpl: 'jansen' }).state.mech.spec).not.toBeNull();
  });

  it('refuses a change of page (its locks would not hold there)', () => {
    const mech = parseUrl('page=mech', DEFAULT_STATE, quiet).state;
    const r = applyPatch(mech, { page: 'sim' });
    expect(r.applied).toEqual([]);
    expect(r.state.shell.page).toBe('mechanism');
  });
});
