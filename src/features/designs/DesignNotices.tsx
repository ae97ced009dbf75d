import { fileStem } from '../../shared/fileNames';
import type { Locale } from '../../shared/state/appState';
import type { RestoreOffer } from './autosave';
import type { DesignsMessages } from './designsMessages';
import { shownTime } from './designsMessages';
import type { DesignNotice } from './useDesignFiles';
import { NoticeCard } from '../../shared/ui/NoticeCard';

/** Props of DesignNotices: the bar's notice, the restore offer, their handlers and strings. */
export interface DesignNoticesProps {
  notice: DesignNotice | null;
  onClose: () => void;
  offer: RestoreOffer | null;
  onRestore: () => void;
  onDismissOffer: () => void;
  t: DesignsMessages;
  locale: Locale;
}

/**
 * The design bar's notices, in a corner over the page: the offer to restore the last session (a region with
 * Restore and Dismiss), then what was saved or opened (a status) or why a file was refused (an alert, kept
 * until closed). The live regions are always in the page, so screen readers announce what appears in them.
 */
export function DesignNotices({ notice, onClose, offer, onRestore, onDismissOffer, t, locale }: DesignNoticesProps) {
  return (
    <div className="design-notices">
      {offer ? (
        <section className="notice-card design-offer" aria-label={t.restore} data-testid="restore-offer">
          <p>
            {t.restoreText(
              offer.name || fileStem(offer.state.design.linkage, offer.state.design.branch),
              offer.savedAt ? shownTime(offer.savedAt, locale) : '',
            )}
          </p>
          <div className="design-notice-actions">
            <button type="button" className="design-notice-primary" onClick={onRestore}>
              {t.restore}
            </button>
            <button type="button" onClick={onDismissOffer}>
              {t.dismiss}
            </button>
          </div>
        </section>
      ) : null}
      <div role="status" className="design-live">
        {notice?.kind === 'status' ? <NoticeCard text={notice.text} onClose={onClose} close={t.closeNotice} /> : null}
      </div>
      <div role="alert" className="design-live" data-testid="design-alert">
        {notice?.kind === 'alert' ? <NoticeCard text={notice.text} onClose={onClose} close={t.closeNotice} /> : null}
      </div>
    </div>
  );
}
