import { memo, useRef } from 'react';
import type { Dispatch, KeyboardEvent } from 'react';
import type { Action, Locale, Page } from '../shared/state/appState';
import { PAGES, PAGE_ORDER } from './pages';

/** Props of PageTabs: the page shown, the language, the dispatcher, the id of the tab panel the tabs control. */
export interface PageTabsProps {
  page: Page;
  locale: Locale;
  dispatch: Dispatch<Action>;
  panelId: string;
}

/** Id of a page's tab, for the tab panel's aria-labelledby. */
export function pageTabId(page: Page): string {
  return `tab-${page}`;
}

/** The page a key moves to from page in the WAI-ARIA tabs pattern (arrows wrap, Home/End), or null. */
export function pageForKey(page: Page, key: string): Page | null {
  const i = PAGE_ORDER.indexOf(page);
  const n = PAGE_ORDER.length;
  if (key === 'ArrowRight') return PAGE_ORDER[(i + 1) % n];
  if (key === 'ArrowLeft') return PAGE_ORDER[(i - 1 + n) % n];
  if (key === 'Home') return PAGE_ORDER[0];
  if (key === 'End') return PAGE_ORDER[n - 1];
  return null;
}

function PageTabsImpl({ page, locale, dispatch, panelId }: PageTabsProps) {
  const tabs = useRef(new Map<Page, HTMLButtonElement>());
  const name = (p: Page) => PAGES[p].label[locale];
  const onKeyDown = (e: KeyboardEvent<HTMLButtonElement>) => {
    const next = pageForKey(page, e.key);
    if (!next) return;
    e.preventDefault();
    // Selection follows focus: the pages switch instantly (the lab's chunk loads behind a fallback).
    tabs.current.get(next)?.focus();
    dispatch({ type: 'setPage', page: next });
  };
  return (
    <div className="page-tabs" role="tablist" aria-label={PAGE_ORDER.map(name).join(' / ')}>
      {PAGE_ORDER.map((p) => (
        <button
          key={p}
          ref={(el) => {
            if (el) tabs.current.set(p, el);
            else tabs.current.delete(p);
          }}
          type="button"
          role="tab"
          id={pageTabId(p)}
          aria-selected={page === p}
          aria-controls={panelId}
          tabIndex={page === p ? 0 : -1}
          className={`page-tab${page === p ? ' active' : ''}`}
          onClick={() => dispatch({ type: 'setPage', page: p })}
          onKeyDown={onKeyDown}
        >
          {name(p)}
        </button>
      ))}
    </div>
  );
}

/**
 * The pages' tabs in the top bar (PAGES, in its order), with the WAI-ARIA tabs keyboard pattern: one Tab stop
 * (roving tabindex), Left/Right arrows move between the tabs and wrap, Home and End go to the first and last.
 */
export const PageTabs = memo(PageTabsImpl);
