import './UrlNotice.css';
import { useState } from 'react';
import type { IgnoredParam } from '../shared/url/url';
import type { IgnoredSource } from '../shared/url/ignoredNotice';
import { ignoredNoticeText } from '../shared/url/ignoredNotice';
import { useMessages } from '../shared/i18n/MessagesContext';
import { NoticeCard } from '../shared/ui/NoticeCard';

/** Props of UrlNotice: the parameters the URL parser ignored (ParsedUrl.ignored). */
export interface UrlNoticeProps {
  ignored: readonly IgnoredParam[];
  /** Where the values came from: a link (default) or the custom element's attributes. */
  source?: IgnoredSource;
}

/**
 * A dismissible notice naming the shared link's parameters that were ignored (bad or unknown values), so a
 * student knows the defaults are shown instead. Renders nothing when none was ignored or once dismissed.
 */
export function UrlNotice({ ignored, source = 'link' }: UrlNoticeProps) {
  const t = useMessages();
  const [dismissed, setDismissed] = useState(false);
  if (dismissed || ignored.length === 0) return null;
  return (
    <div role="status" data-testid="url-notice" className="url-notice">
      <NoticeCard
        text={ignoredNoticeText(ignored, t, source)}
        close={t.urlNoticeDismiss}
        onClose={() => setDismissed(true)}
      />
    </div>
  );
}
