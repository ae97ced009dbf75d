import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import { ignoredNoticeText } from '../../../src/shared/url/ignoredNotice';
import { messagesEn } from '../../../src/shared/i18n/messagesEn';
import { messagesZhTw } from '../../../src/shared/i18n/messagesZhTw';
import { parseUrl } from '../../../src/shared/url/url';

const quiet = () => undefined;

describe('ignoredNoticeText', () => {
  it('names the ignored key and its value in English and zh-TW', () => {
    const { ignored } = parseUrl('r3=abc&r1=5', DEFAULT_STATE, quiet);
    expect(ignoredNoticeText(ignored, messagesEn)).toBe(
      'This link has a value the lab cannot use, so the default is shown instead: r3 = “abc”.',
    );
    expect(ignoredNoticeText(ignored, messagesZhTw)).toBe(
      '此連結有一個本工具無法使用的值，已改用預設值：r3 =「abc」。',
    );
  });

  it("says 'element' and 'attribute' for a <fourbar-lab>'s attributes, not 'link'", () => {
    const { ignored } = parseUrl('r3=abc&r1=5', DEFAULT_STATE, quiet);
    expect(ignoredNoticeText(ignored, messagesEn, 'attributes')).toBe(
      'This element has an attribute value the lab cannot use, so the default is shown instead: r3 = “abc”.',
    );
    expect(ignoredNoticeText(ignored, messagesZhTw, 'attributes')).toBe(
      '此元素有一個本工具無法使用的屬性值，已改用預設值：r3 =「abc」。',
    );
  });

  it('counts several and lists at most four, then how many more', () => {
    const { ignored } = parseUrl('r1=a&r2=b&r3=c&r4=d&t2=e&br=f', DEFAULT_STATE, quiet);
    const en = ignoredNoticeText(ignored, messagesEn);
    expect(en).toContain('This link has 6 values');
    expect(en).toContain('r4 = “d”, and 2 more.');
    expect(en).not.toContain('t2');
    expect(ignoredNoticeText(ignored, messagesZhTw)).toContain('r4 =「d」、另有 2 個');
  });

  it('shortens a 400-character value with an ellipsis', () => {
    const { ignored } = parseUrl(`r2=${'1'.repeat(400)}x`, DEFAULT_STATE, quiet);
    const text = ignoredNoticeText(ignored, messagesEn);
    expect(text).toContain(`r2 = “${'1'.repeat(23)}…”`);
    expect(text.length).toBeLessThan(140);
  });

  it('is empty when nothing was ignored', () => {
    expect(ignoredNoticeText([], messagesEn)).toBe('');
  });
});
