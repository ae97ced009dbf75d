import { createElement } from 'react';
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { MessagesContext } from '../../src/shared/i18n/MessagesContext';
import { UrlNotice } from '../../src/app/UrlNotice';
import { DEFAULT_STATE } from '../../src/shared/state/appState';
import { messagesZhTw } from '../../src/shared/i18n/messagesZhTw';
import { parseUrl } from '../../src/shared/url/url';

const quiet = () => undefined;

describe('UrlNotice', () => {
  it('is a status naming the ignored key, with a dismiss button, in the current language', () => {
    const { ignored } = parseUrl('r3=abc', DEFAULT_STATE, quiet);
    const html = renderToStaticMarkup(
      createElement(MessagesContext.Provider, { value: messagesZhTw }, createElement(UrlNotice, { ignored })),
    );
    expect(html).toContain('role="status"');
    expect(html).toContain('r3 =「abc」');
    expect(html).toContain('aria-label="關閉"');
  });

  it('renders nothing when no parameter was ignored', () => {
    expect(renderToStaticMarkup(createElement(UrlNotice, { ignored: [] }))).toBe('');
  });
});
