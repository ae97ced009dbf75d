import type { Locale } from '../../shared/state/appState';
import { messageModule } from '../../shared/i18n/messageModule';
import type { MechMessages } from './mechMessagesEn';
import { mechMessagesEn } from './mechMessagesEn';
import { mechMessagesZhTw } from './mechMessagesZhTw';

export type { MechMessages } from './mechMessagesEn';

/** The mechanism page's strings in every language (both bundled with the page's chunk). */
export const mechMessages = messageModule<MechMessages>(mechMessagesEn, { 'zh-TW': mechMessagesZhTw });

/** The mechanism page's strings in a language. */
export function mechMessagesFor(locale: Locale): MechMessages {
  return mechMessages.get(locale);
}
