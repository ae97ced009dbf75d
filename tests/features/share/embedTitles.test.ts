import { describe, expect, it } from 'vitest';
import { messagesEn } from '../../../src/shared/i18n/messagesEn';
import { messagesZhTw } from '../../../src/shared/i18n/messagesZhTw';
import { EMBED_PAGES } from '../../../src/shared/url/url';

describe('embedTitles', () => {
  it('names the page an embed shows, in English: the simulator, the Mechanisms page, the Spatial page', () => {
    expect(messagesEn.embedTitles.simulator).toBe('Four-bar linkage simulator');
    expect(messagesEn.embedTitles.mechanism).toMatch(/mechanism/i);
    expect(messagesEn.embedTitles.spatial).toMatch(/spatial/i);
    for (const page of ['mechanism', 'spatial'] as const)
      expect(messagesEn.embedTitles[page]).not.toMatch(/simulator/i);
  });

  it('names them in Traditional Chinese too (模擬器 only for the simulator)', () => {
    expect(messagesZhTw.embedTitles.simulator).toBe('四連桿機構模擬器');
    expect(messagesZhTw.embedTitles.mechanism).toContain('機構');
    expect(messagesZhTw.embedTitles.spatial).toContain('空間');
    for (const page of ['mechanism', 'spatial'] as const)
      expect(messagesZhTw.embedTitles[page]).not.toContain('模擬器');
  });

  it('has one distinct title per embed page in each language', () => {
    for (const t of [messagesEn, messagesZhTw]) {
      expect(Object.keys(t.embedTitles).sort()).toEqual([...EMBED_PAGES].sort());
      expect(new Set(Object.values(t.embedTitles)).size).toBe(EMBED_PAGES.length);
    }
  });
});
