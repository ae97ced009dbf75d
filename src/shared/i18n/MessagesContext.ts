import { createContext, useContext } from 'react';
import type { Messages } from './messages';
import { messagesEn } from './messagesEn';

/** The current language's strings; English until a provider says otherwise. */
export const MessagesContext = createContext<Messages>(messagesEn);

/** The current language's strings. */
export function useMessages(): Messages {
  return useContext(MessagesContext);
}
