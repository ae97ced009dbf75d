import { memo } from 'react';
import type { Dispatch } from 'react';
import type { Action, Locale } from '../shared/state/appState';
import { LOCALES } from '../shared/i18n/i18n';
import { loadLanguage } from '../shared/i18n/messageModule';
import { LOCALE_STORAGE_KEY, writeStorage } from '../shared/storage';
import { Icon } from '../shared/ui/Icon';
import { useMessages } from '../shared/i18n/MessagesContext';
import { SelectMenu } from '../shared/ui/SelectMenu';

/** Props of LanguageSelect: the current language and the dispatcher that changes it. */
export interface LanguageSelectProps {
  locale: Locale;
  dispatch: Dispatch<Action>;
}

function LanguageSelectImpl({ locale, dispatch }: LanguageSelectProps) {
  const t = useMessages();
  return (
    <label className="lang-select">
      <span className="sr-only">{t.language}</span>
      <span className="lang-icon">
        <Icon name="language" />
      </span>
      <SelectMenu<Locale>
        label={t.language}
        value={locale}
        options={LOCALES.map((l) => ({ value: l, label: t.languageNames[l] }))}
        onChange={(l) => {
          writeStorage(LOCALE_STORAGE_KEY, l);
          // The state changes once the strings are there, so no frame shows a mix of languages.
          loadLanguage(l).then(
            () => dispatch({ type: 'setLocale', locale: l }),
            () => dispatch({ type: 'setLocale', locale: l }),
          );
        }}
      />
    </label>
  );
}

/** The language menu (each language named in its own words); the choice is remembered in local storage. */
export const LanguageSelect = memo(LanguageSelectImpl);
