import { describe, expect, it } from 'vitest';
import { PAGES, PAGE_ORDER } from '../../src/app/pages';
import { pageForKey } from '../../src/app/PageTabs';
import { DEFAULT_STATE } from '../../src/shared/state/appState';
import { PAGE_URL_VALUES } from '../../src/shared/state/slices/shellSlice';
import { parseUrl, serializeState } from '../../src/shared/url/url';

describe('PAGES', () => {
  it('has one entry per page of the shell slice, in the tabs order, each named in every language', () => {
    expect(PAGE_ORDER).toEqual(Object.keys(PAGE_URL_VALUES));
    for (const page of PAGE_ORDER) {
      expect(PAGES[page].label.en, page).not.toBe('');
      expect(PAGES[page].label['zh-TW'], page).not.toBe('');
    }
  });

  it('gives every page its URL value: page=sim, page=lab, page=syn, page=mech', () => {
    expect(PAGE_URL_VALUES).toEqual({ simulator: 'sim', lab: 'lab', synthesis: 'syn', mechanism: 'mech' });
    for (const page of PAGE_ORDER) {
      const q = serializeState({ ...DEFAULT_STATE, shell: { ...DEFAULT_STATE.shell, page } });
      expect(parseUrl(q, DEFAULT_STATE, () => {}).state.shell.page).toBe(page);
      expect(parseUrl(`page=${PAGE_URL_VALUES[page]}`, DEFAULT_STATE, () => {}).state.shell.page).toBe(page);
    }
  });

  it('orders the tabs for the arrow keys (wrapping), Home and End', () => {
    expect(pageForKey('simulator', 'ArrowRight')).toBe('lab');
    expect(pageForKey('mechanism', 'ArrowRight')).toBe('simulator');
    expect(pageForKey('simulator', 'ArrowLeft')).toBe('mechanism');
    expect(pageForKey('lab', 'Home')).toBe('simulator');
    expect(pageForKey('lab', 'End')).toBe('mechanism');
    expect(pageForKey('lab', 'a')).toBeNull();
  });
});
