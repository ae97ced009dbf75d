import './EmbedLayout.css';
import { useCallback, useMemo, useState } from 'react';
import type { Dispatch } from 'react';
import type { Action, AppState } from '../shared/state/appState';
import type { EmbedOptions, EmbedPage, ParsedUrl } from '../shared/url/url';
import { appUrl, isEmbedPage } from '../shared/url/url';
import { PAGE_URL_VALUES } from '../shared/state/slices/shellSlice';
import type { EmbedBridge } from '../features/share/embedBridge';
import { frameBridge } from '../features/share/embedBridge';
import { EMBED_VIEWS } from './embedPages';
import { LanguageSelect } from './LanguageSelect';
import { FramePoseProvider } from '../features/simulator/FramePoseProvider';
import { MessagesContext, useMessages } from '../shared/i18n/MessagesContext';
import { useDocumentMeta } from './useDocumentMeta';
import { useSimulatorSession } from './useSimulatorSession';
import type { ShownFor } from './useSimulatorSession';
import { useEmbedMessages } from '../features/share/useEmbedMessages';
import { useUrlSync } from './useUrlSync';
import { UrlNotice } from './UrlNotice';

/** Props of EmbedLayout: the state and the embed options (panels shown, parameters locked) parsed from the URL. */
export interface EmbedLayoutProps {
  initial: ParsedUrl;
  /** How the widget talks to its host; default: postMessage with the parent window (frameBridge). */
  bridge?: EmbedBridge;
  /** Panels and locks when the host changes them later (the custom element's attributes); default initial.embed. */
  embed?: EmbedOptions;
  /**
   * Whether the widget owns its page (embed.html, default): it sets the document's title and language and keeps
   * the address bar in step. The custom element, inside someone else's page, does neither.
   */
  ownsPage?: boolean;
}

/** The link to the full simulator with this state, or '' where the frame's address cannot be read. */
function fullAppHref(state: AppState): string {
  try {
    return appUrl(window.location.href, state);
  } catch {
    return '';
  }
}

/** Props of EmbedBar: the state, its dispatch, the full app's link ('' for none) and the page shown (its title). */
interface EmbedBarProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  fullHref: string;
  page: EmbedPage;
}

/** The widget's title bar: the page's title, the language, and a link to the full simulator where there is one. */
function EmbedBar({ state, dispatch, fullHref, page }: EmbedBarProps) {
  const t = useMessages();
  return (
    <header className="embed-bar">
      <h1 className="embed-title">{t.embedTitles[page]}</h1>
      <div className="embed-bar-right">
        <LanguageSelect locale={state.shell.locale} dispatch={dispatch} />
        {fullHref ? (
          <a className="embed-link" href={fullHref} target="_blank" rel="noopener noreferrer">
            {t.openFull} ↗
          </a>
        ) : null}
      </div>
    </header>
  );
}

/**
 * The parsed URL with a page that embeds: a page without an embed (page=lab) shows the simulator's, and the notice
 * says so.
 */
export function embeddable(initial: ParsedUrl): ParsedUrl {
  const page = initial.state.shell.page;
  if (isEmbedPage(page)) return initial;
  const value = PAGE_URL_VALUES[page];
  const why = `page=${value} has no embed; the simulator is shown`;
  return {
    ...initial,
    state: { ...initial.state, shell: { ...initial.state.shell, page: 'simulator' } },
    warnings: [...initial.warnings, `Ignoring URL parameter page="${value}": ${why}.`],
    ignored: [...initial.ignored, { key: 'page', value, shownKey: 'page', shownValue: value, why }],
  };
}

/**
 * The compact widget for an iframe: title bar with language and a link to the full simulator, the linkage
 * with the controls beside it, then the panels the URL asks for (numbers, plots, export).
 */
export function EmbedLayout(props: EmbedLayoutProps) {
  const { bridge: givenBridge, embed: givenEmbed, ownsPage = true } = props;
  const initial = useMemo(() => embeddable(props.initial), [props.initial]);
  const embed = givenEmbed ?? initial.embed;
  const [ownBridge] = useState(() => (givenBridge ? null : frameBridge()));
  const bridge = givenBridge ?? ownBridge;
  const plotsShown = embed.panels.includes('plots');
  const numbersShown = embed.panels.includes('info');
  const shownFor = useCallback<ShownFor>(
    (_s, plotPixels) => ({ stage: true, plotPixels: plotsShown ? plotPixels : 0, newton: numbersShown }),
    [plotsShown, numbersShown],
  );
  const session = useSimulatorSession(initial.state, shownFor, numbersShown);
  const { state, dispatch, cycle, point, t, playhead } = session;
  // The page's view from the registry; the options it does not offer were refused when the URL was read.
  const page = isEmbedPage(state.shell.page) ? state.shell.page : 'simulator';
  useDocumentMeta(t.htmlLang, t.embedTitles[page], ownsPage);
  useUrlSync(state, embed, ownsPage);
  useEmbedMessages(bridge, state, dispatch, embed.locked);

  // The full app lives beside embed.html; a page hosting the element has no such neighbour.
  const fullHref = ownsPage ? fullAppHref(state) : '';
  return (
    <MessagesContext.Provider value={t}>
      <FramePoseProvider state={state} playhead={playhead} scrub={session.scrub} ghostShown>
        <div className="embed" lang={t.htmlLang} data-ready={cycle && point ? 'true' : 'false'}>
          <EmbedBar state={state} dispatch={dispatch} fullHref={fullHref} page={page} />
          <UrlNotice ignored={initial.ignored} source={ownsPage ? 'link' : 'attributes'} />
          <main className="embed-main">{EMBED_VIEWS[page]({ session, embed })}</main>
        </div>
      </FramePoseProvider>
    </MessagesContext.Provider>
  );
}
