import { createContext, useContext } from 'react';
import type { Messages } from '../state/messages';
import { messagesEn } from '../state/messagesEn';

/** The current language's strings; English until a provider says otherwise. */
export const MessagesContext = createContext<Messages>(messagesEn);

/** The current language's strings. */
export function useMessages(): Messages {
  return useContext(MessagesContext);
}
