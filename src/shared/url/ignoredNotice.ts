import type { Messages } from '../i18n/messages';
import type { IgnoredParam } from './url';

/** Most ignored parameters a notice names one by one; the rest are counted ("and 3 more"). */
export const NOTICE_MAX_LISTED = 4;

/** Where the ignored values came from: a link's query, or a <fourbar-lab> element's attributes. */
export type IgnoredSource = 'link' | 'attributes';

/** The notice text for ignored URL parameters (or element attributes), in the UI's language; '' when none was ignored. */
export function ignoredNoticeText(
  ignored: readonly IgnoredParam[],
  t: Messages,
  source: IgnoredSource = 'link',
): string {
  if (ignored.length === 0) return '';
  const listed = ignored.slice(0, NOTICE_MAX_LISTED).map((p) => t.urlIgnoredParam(p.shownKey, p.shownValue));
  const rest = ignored.length - listed.length;
  if (rest > 0) listed.push(t.urlIgnoredMore(String(rest)));
  const text = source === 'attributes' ? t.attributesIgnored : t.urlIgnored;
  return text(listed.join(t.urlIgnoredSeparator), ignored.length);
}
