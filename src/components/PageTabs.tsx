import { memo } from 'react';
import type { Dispatch } from 'react';
import type { Action, Page } from '../state/appState';
import { useMessages } from './MessagesContext';

/** Props of PageTabs: the page shown, the dispatcher, and the id of the tab panel the tabs control. */
export interface PageTabsProps {
  page: Page;
  dispatch: Dispatch<Action>;
  panelId: string;
}

/** Id of a page's tab, for the tab panel's aria-labelledby. */
export function pageTabId(page: Page): string {
  return `tab-${page}`;
}

const PAGES: readonly Page[] = ['simulator', 'lab'];

function PageTabsImpl({ page, dispatch, panelId }: PageTabsProps) {
  const t = useMessages();
  return (
    <div className="page-tabs" role="tablist" aria-label={`${t.viewSimulator} / ${t.viewLab}`}>
      {PAGES.map((p) => (
        <button
          key={p}
          type="button"
          role="tab"
          id={pageTabId(p)}
          aria-selected={page === p}
          aria-controls={panelId}
          className={`page-tab${page === p ? ' active' : ''}`}
          onClick={() => dispatch({ type: 'setPage', page: p })}
        >
          {p === 'simulator' ? t.viewSimulator : t.viewLab}
        </button>
      ))}
    </div>
  );
}

/** The Simulator / Solver lab tabs in the top bar. */
export const PageTabs = memo(PageTabsImpl);
