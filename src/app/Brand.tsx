import { useMessages } from '../shared/i18n/MessagesContext';

/** The app's logo (a four-bar drawn in four strokes), title and subtitle, for the top bar. */
export function Brand() {
  const t = useMessages();
  return (
    <div className="brand">
      <svg className="logo" viewBox="0 0 32 32" aria-hidden="true">
        <path
          d="M5 25 L11 12 L24 9 L27 25"
          fill="none"
          stroke="currentColor"
          strokeWidth="2.4"
          strokeLinejoin="round"
        />
        <circle cx="5" cy="25" r="2.6" fill="#fff" stroke="currentColor" strokeWidth="1.6" />
        <circle cx="27" cy="25" r="2.6" fill="#fff" stroke="currentColor" strokeWidth="1.6" />
        <circle cx="11" cy="12" r="2.2" fill="#fff" stroke="currentColor" strokeWidth="1.6" />
        <circle cx="24" cy="9" r="2.2" fill="#fff" stroke="currentColor" strokeWidth="1.6" />
      </svg>
      <div>
        <h1 className="app-title">{t.appTitle}</h1>
        <p className="app-subtitle">{t.appSubtitle}</p>
      </div>
    </div>
  );
}
