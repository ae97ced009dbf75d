import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import { isShareLink, restoreOffer, sameWork } from '../../../src/features/designs/autosave';
import { writeDesignFile } from '../../../src/features/designs/designFile';
import { withFields } from '../../shared/state/stateFixtures';

const AT = new Date('2026-01-19T10:30:00.000Z');
const EDITED = withFields(DEFAULT_STATE, { linkage: { r1: 7, r2: 2, r3: 5, r4: 5 }, omegaUnit: 'rpm' });

describe('isShareLink', () => {
  it('is a link with any parameter but the language and the page', () => {
    expect(isShareLink('')).toBe(false);
    expect(isShareLink('?')).toBe(false);
    expect(isShareLink('?lang=zh-TW')).toBe(false);
    expect(isShareLink('lang=en&page=lab')).toBe(false);
    expect(isShareLink('?r1=7')).toBe(true);
    expect(isShareLink('?lang=en&play=1')).toBe(true);
    expect(isShareLink('?bogus=1')).toBe(true);
  });
});

describe('sameWork', () => {
  it('ignores the language, the page and Play and sees everything else', () => {
    expect(sameWork(DEFAULT_STATE, withFields(DEFAULT_STATE, { locale: 'zh-TW', page: 'lab', playing: true }))).toBe(
      true,
    );
    expect(sameWork(DEFAULT_STATE, withFields(DEFAULT_STATE, { omegaUnit: 'rpm' }))).toBe(false);
    expect(sameWork(DEFAULT_STATE, withFields(DEFAULT_STATE, { view: { zoom: 2, panX: 0, panY: 0 } }))).toBe(false);
  });
});

describe('restoreOffer', () => {
  const autosave = writeDesignFile(EDITED, 'session', AT);

  it('offers an autosave whose work differs from the start, with its name and time', () => {
    const offer = restoreOffer(autosave, DEFAULT_STATE, '');
    expect(offer).toMatchObject({ name: 'session', savedAt: '2026-01-19T10:30:00.000Z' });
    expect(offer?.state.design.linkage.r1).toBe(7);
    expect(offer?.state.motion.omegaUnit).toBe('rpm');
  });

  it('offers nothing without an autosave, for a share link, for the same work, or for an unreadable autosave', () => {
    expect(restoreOffer(null, DEFAULT_STATE, '')).toBeNull();
    expect(restoreOffer(autosave, DEFAULT_STATE, '?r1=7')).toBeNull();
    expect(restoreOffer(autosave, withFields(EDITED, { locale: 'zh-TW' }), '?lang=zh-TW')).toBeNull();
    expect(restoreOffer('{"format":', DEFAULT_STATE, '')).toBeNull();
  });

  it('still offers when only the language or the page is in the address', () => {
    expect(restoreOffer(autosave, DEFAULT_STATE, '?lang=zh-TW&page=lab')).not.toBeNull();
  });
});
