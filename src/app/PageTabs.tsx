import { memo, useRef } from 'react';
import type { Dispatch, KeyboardEvent } from 'react';
import type { Action, Page } from '../shared/state/appState';
import { useMessages } from '../shared/i18n/MessagesContext';

/** Props of PageTabs: the page shown, the dispatcher, the id of the tab panel the tabs control, the synthesis tab's name. */
export interface PageTabsProps {
  page: Page;
  dispatch: Dispatch<Action>;
  panelId: string;
  synthesisLabel: string;
}

/** Id of a page's tab, for the tab panel's aria-labelledby. */
export function pageTabId(page: Page): string {
  return `tab-${page}`;
}

const PAGES: readonly Page[] = ['simulator', 'lab', 'synthesis'];

/** The page a key moves to from page in the WAI-ARIA tabs pattern (arrows wrap, Home/End), or null. */
export function pageForKey(page: Page, key: string): Page | null {
  const i = PAGES.indexOf(page);
  const n = PAGES.length;
  if (key === 'ArrowRight') return PAGES[(i + 1) % n];
  if (key === 'ArrowLeft') return PAGES[(i - 1 + n) % n];
  if (key === 'Home') return PAGES[0];
  if (key === 'End') return PAGES[n - 1];
  return null;
}

function PageTabsImpl({ page, dispatch, panelId, synthesisLabel }: PageTabsProps) {
  const t = useMessages();
  const tabs = useRef(new Map<Page, HTMLButtonElement>());
  const names: Record<Page, string> = { simulator: t.viewSimulator, lab: t.viewLab, synthesis: synthesisLabel };
  const onKeyDown = (e: KeyboardEvent<HTMLButtonElement>) => {
    const next = pageForKey(page, e.key);
    if (!next) return;
    e.preventDefault();
    // Selection follows focus: the pages switch instantly (the lab's chunk loads behind a fallback).
    tabs.current.get(next)?.focus();
    dispatch({ type: 'setPage', page: next });
  };
  return (
    <div className="page-tabs" role="tablist" aria-label={PAGES.map((p) => names[p]).join(' / ')}>
      {PAGES.map((p) => (
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
          {names[p]}
        </button>
      ))}
    </div>
  );
}

/**
 * The Simulator / Solver lab / Synthesis tabs in the top bar, with the WAI-ARIA tabs keyboard pattern: one Tab stop
 * (roving tabindex), Left/Right arrows move between the tabs and wrap, Home and End go to the first and last.
 */
export const PageTabs = memo(PageTabsImpl);
