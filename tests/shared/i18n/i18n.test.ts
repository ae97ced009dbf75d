import { describe, expect, it } from 'vitest';
import { detectLocale, getMessages, matchLocale, parseLocale } from '../../../src/shared/i18n/i18n';
import { loadLanguage, messageModule } from '../../../src/shared/i18n/messageModule';
import { messagesEn } from '../../../src/shared/i18n/messagesEn';
import { messagesZhTw } from '../../../src/shared/i18n/messagesZhTw';
import { labMessagesFor } from '../../../src/features/lab/labMessages';
import { labMessagesEn } from '../../../src/features/lab/labMessagesEn';
import { labMessagesZhTw } from '../../../src/features/lab/labMessagesZhTw';

function shape(o: unknown): unknown {
  if (typeof o === 'function') return 'fn';
  if (o && typeof o === 'object')
    return Object.fromEntries(
      Object.keys(o)
        .sort()
        .map((k) => [k, shape((o as Record<string, unknown>)[k])]),
    );
  return typeof o;
}

describe('messages', () => {
  it('has the same keys in English and Traditional Chinese', () => {
    expect(shape(messagesZhTw)).toEqual(shape(messagesEn));
    expect(shape(labMessagesZhTw)).toEqual(shape(labMessagesEn));
  });

  it('gives the lab its strings in the language asked for, and never a key twice across the two tables', () => {
    expect(labMessagesFor('en')).toBe(labMessagesEn);
    expect(labMessagesFor('zh-TW')).toBe(labMessagesZhTw);
    const app = new Set(Object.keys(messagesEn));
    expect(Object.keys(labMessagesEn).filter((k) => app.has(k))).toEqual([]);
  });

  it('has no empty string in either language', () => {
    const walk = (o: unknown, path: string): void => {
      if (typeof o === 'string') expect(o.trim(), path).not.toBe('');
      else if (o && typeof o === 'object') for (const [k, v] of Object.entries(o)) walk(v, `${path}.${k}`);
    };
    walk(messagesEn, 'en');
    walk(messagesZhTw, 'zh-TW');
    walk(labMessagesEn, 'lab en');
    walk(labMessagesZhTw, 'lab zh-TW');
  });

  it('starts the English field labels with r1..r4 and θ2, and export buttons with Export', () => {
    for (const f of ['r1', 'r2', 'r3', 'r4'] as const) expect(messagesEn.fieldLabels[f].startsWith(f)).toBe(true);
    expect(messagesEn.fieldLabels.theta2.startsWith('θ2')).toBe(true);
    expect(messagesEn.play).toBe('Play');
    expect(messagesEn.pause).toBe('Pause');
    for (const k of [
      'exportLinkage',
      'exportTheta3',
      'exportTheta4',
      'exportBoth',
      'exportOmega',
      'exportAlpha',
      'exportConvergence',
      'exportCsv',
    ] as const) {
      expect(messagesEn[k].startsWith('Export')).toBe(true);
    }
  });

  it('keeps the symbols first in Chinese labels too', () => {
    for (const f of ['r1', 'r2', 'r3', 'r4'] as const) expect(messagesZhTw.fieldLabels[f].startsWith(f)).toBe(true);
    expect(messagesZhTw.fieldLabels.theta2.startsWith('θ2')).toBe(true);
  });
});

describe('detectLocale', () => {
  it('picks zh-TW for Traditional Chinese browsers and English otherwise', () => {
    expect(detectLocale(['zh-TW', 'en'])).toBe('zh-TW');
    expect(detectLocale(['zh-Hant-HK'])).toBe('zh-TW');
    expect(detectLocale(['fr-FR', 'en-GB'])).toBe('en');
    expect(detectLocale(['zh-CN'])).toBe('en');
    expect(detectLocale([])).toBe('en');
  });
  it('matches and parses tags', () => {
    expect(matchLocale('EN-us')).toBe('en');
    expect(parseLocale('zh-tw')).toBe('zh-TW');
    expect(parseLocale('zh')).toBeNull();
  });
});

describe('loadLanguage', () => {
  it('serves English until zh-TW is loaded, then the zh-TW table', async () => {
    expect(getMessages('en').play).toBe('Play');
    await loadLanguage('zh-TW');
    expect(getMessages('zh-TW').play).toBe('播放');
  });
});

describe('messageModule', () => {
  it('serves English until a language loads, then that table; bundled tables need no load', async () => {
    const loads: string[] = [];
    const lazy = messageModule(
      { hello: 'hello' },
      {
        'zh-TW': async () => {
          loads.push('zh-TW');
          return { hello: '你好' };
        },
      },
    );
    const bundled = messageModule({ hello: 'hi' }, { 'zh-TW': { hello: '嗨' } });
    expect(lazy.get('zh-TW').hello).toBe('hello');
    expect(bundled.get('zh-TW').hello).toBe('嗨');
    await loadLanguage('zh-TW');
    expect(lazy.get('zh-TW').hello).toBe('你好');
    expect(lazy.get('en').hello).toBe('hello');
    // One load per language, however often it is asked for.
    await loadLanguage('zh-TW');
    await lazy.load('zh-TW');
    expect(loads).toEqual(['zh-TW']);
  });
});
