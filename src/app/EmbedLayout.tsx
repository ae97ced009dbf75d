import './EmbedLayout.css';
import { Suspense, lazy, useCallback, useState } from 'react';
import type { Dispatch } from 'react';
import type { Action, AppState } from '../shared/state/appState';
import type { EmbedOptions, EmbedPanel, ParsedUrl } from '../shared/url/url';
import { appUrl } from '../shared/url/url';
import { ControlsPanel } from '../features/simulator/ControlsPanel';
import type { EmbedBridge } from '../features/share/embedBridge';
import { frameBridge } from '../features/share/embedBridge';
import { EmbedPanels } from './EmbedPanels';
import { LanguageSelect } from './LanguageSelect';
import { FramePoseProvider } from '../features/simulator/FramePoseProvider';
import { LinkageStage } from '../features/simulator/LinkageStage';
import { createForceLayer } from '../features/forces/forceLayer';
import { MessagesContext, useMessages } from '../shared/i18n/MessagesContext';
import { shellMessages } from './shellMessages';
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

/** The widget's title bar: its title, the language, and a link to the full simulator where there is one. */
function EmbedBar({ state, dispatch, fullHref }: { state: AppState; dispatch: Dispatch<Action>; fullHref: string }) {
  const t = useMessages();
  return (
    <header className="embed-bar">
      <h1 className="embed-title">{t.embedTitle}</h1>
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

// The mechanism page (page=mech) loads only when an embed asks for it.
const MechanismPage = lazy(() =>
  import('../features/mechanism/MechanismPage').then((m) => ({ default: m.MechanismPage })),
);

/**
 * The compact widget for an iframe: title bar with language and a link to the full simulator, the linkage
 * with the controls beside it, then the panels the URL asks for (numbers, plots, export).
 */
export function EmbedLayout({ initial, bridge: givenBridge, embed: givenEmbed, ownsPage = true }: EmbedLayoutProps) {
  const embed = givenEmbed ?? initial.embed;
  const [ownBridge] = useState(() => (givenBridge ? null : frameBridge()));
  const [forceLayer] = useState(createForceLayer);
  const bridge = givenBridge ?? ownBridge;
  const show = (p: EmbedPanel) => embed.panels.includes(p);
  const plotsShown = embed.panels.includes('plots');
  const numbersShown = embed.panels.includes('info');
  const shownFor = useCallback<ShownFor>(
    (_s, plotPixels) => ({ stage: true, plotPixels: plotsShown ? plotPixels : 0, newton: numbersShown }),
    [plotsShown, numbersShown],
  );
  const session = useSimulatorSession(initial.state, shownFor, numbersShown);
  const { state, dispatch, cycle, point, t, rocking, design, playhead, onStep, onShown } = session;
  const { onCanvasSize, onTheta2, onCoupler, onViewChange } = session;
  const crankMovable = !embed.locked.includes('theta2');
  const couplerMovable = !embed.locked.includes('coupler');
  const shell = shellMessages(state.shell.locale);
  useDocumentMeta(t.htmlLang, t.embedTitle, ownsPage);
  useUrlSync(state, embed, ownsPage);
  useEmbedMessages(bridge, state, dispatch, embed.locked);

  // The full app lives beside embed.html; a page hosting the element has no such neighbour.
  const fullHref = ownsPage ? fullAppHref(state) : '';
  return (
    <MessagesContext.Provider value={t}>
      <FramePoseProvider state={state} playhead={playhead} scrub={session.scrub} ghostShown>
        <div className="embed" lang={t.htmlLang} data-ready={cycle && point ? 'true' : 'false'}>
          <EmbedBar state={state} dispatch={dispatch} fullHref={fullHref} />
          <UrlNotice ignored={initial.ignored} source={ownsPage ? 'link' : 'attributes'} />
          <main className="embed-main">
            {state.shell.page === 'mechanism' ? (
              <Suspense fallback={null}>
                <MechanismPage state={state} dispatch={dispatch} client={session.client} embedded />
              </Suspense>
            ) : (
              <>
                <div className={`embed-body${show('controls') ? ' with-controls' : ''}`}>
                  <div className="embed-stage">
                    <LinkageStage
                      cycle={cycle}
                      design={design}
                      onViewChange={onViewChange}
                      onTheta2={crankMovable ? onTheta2 : undefined}
                      onCoupler={couplerMovable ? onCoupler : undefined}
                      onSize={onCanvasSize}
                      hint={shell.canvasHint({ crank: crankMovable, coupler: couplerMovable })}
                      onShown={onShown}
                      forceLayer={forceLayer}
                      stage={session.stage}
                    />
                  </div>
                  {show('controls') ? (
                    <div className="embed-controls">
                      <ControlsPanel
                        state={state}
                        dispatch={dispatch}
                        locked={embed.locked}
                        compact
                        rocking={rocking}
                        onStep={onStep}
                      />
                    </div>
                  ) : null}
                </div>
                <EmbedPanels session={session} show={show} theta2Locked={!crankMovable} />
              </>
            )}
          </main>
        </div>
      </FramePoseProvider>
    </MessagesContext.Provider>
  );
}
