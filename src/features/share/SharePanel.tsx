import './SharePanel.css';
import { Suspense, lazy, memo, useState } from 'react';
import type { RefObject } from 'react';
import type { AppState, Page } from '../../shared/state/appState';
import { reducer } from '../../shared/state/appState';
import type { EmbedPresetId } from './embedSnippet';
import { DEFAULT_EMBED_PRESET, EMBED_PRESETS, embedSnippet } from './embedSnippet';
import type { EmbedOptions, EmbedPanel, LockableParam } from '../../shared/url/url';
import {
  DEFAULT_EMBED,
  EMBED_PAGES,
  embedUrl,
  isEmbedPage,
  pageEmbedOptions,
  serializeState,
} from '../../shared/url/url';
import { copyText } from '../../shared/ui/clipboard';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { ShareText } from './ShareText';

/** Props of SharePanel: how to read the state to share when a copy button is pressed. */
export interface SharePanelProps {
  /** The latest committed state; read on click, so the panel does not re-render while the state changes. */
  stateRef: RefObject<AppState>;
  /** The page's own address; default window.location.href (a file: address is the offline copy). */
  pageHref?: string;
  /** A page's name as its tab shows it (the generator's page choice); default its id. */
  pageLabel?: (page: Page) => string;
}

/** Whether the app runs as a file on this computer (the offline single file): its links only work here. */
export function isOfflineFile(href: string): boolean {
  return href.startsWith('file:');
}

// The generator's controls, preview and code load on first open: the app's first load does not carry them.
const EmbedGenerator = lazy(() => import('./EmbedGenerator').then((m) => ({ default: m.EmbedGenerator })));

function presetOf(id: EmbedPresetId) {
  return EMBED_PRESETS.find((p) => p.id === id) ?? DEFAULT_EMBED_PRESET;
}

/** The list with item added (kept in the order of all) or removed. */
function toggled<T>(all: readonly T[], list: readonly T[], item: T, on: boolean): T[] {
  return on ? all.filter((x) => x === item || list.includes(x)) : list.filter((x) => x !== item);
}

/** Copies a text to the clipboard; status says whether it worked, shown is the text (to copy by hand if not). */
function useCopy() {
  const t = useMessages();
  const [status, setStatus] = useState('');
  const [shown, setShown] = useState<string | null>(null);
  const copy = async (text: string) => {
    const ok = await copyText(text);
    setStatus(ok ? t.copied : t.copyFailed);
    setShown(text);
  };
  return { status, shown, copy };
}

/** The embed options kept where the page offers them (its panels and locks, PAGE_EMBEDS). */
function forPage(e: EmbedOptions, page: Page): EmbedOptions {
  const o = pageEmbedOptions(page);
  return { panels: e.panels.filter((p) => o.panels.includes(p)), locked: e.locked.filter((l) => o.locks.includes(l)) };
}

function SharePanelImpl({ stateRef, pageHref = window.location.href, pageLabel = (p) => p }: SharePanelProps) {
  const t = useMessages();
  const [embed, setEmbed] = useState<EmbedOptions>(DEFAULT_EMBED);
  // The page the embed shows; the generator's page choice changes it.
  const [embedPage, setEmbedPage] = useState<Page>('simulator');
  const [presetId, setPresetId] = useState<EmbedPresetId>(DEFAULT_EMBED_PRESET.id);
  const { status, shown, copy } = useCopy();
  // The generator (options, preview, code) renders only once opened; its URL is taken when an option changes.
  const [src, setSrc] = useState<string | null>(null);

  const pausedState = () => reducer(stateRef.current, { type: 'setPlaying', playing: false });
  const onPage = (page: Page): AppState => {
    const s = pausedState();
    return { ...s, shell: { ...s.shell, page } };
  };
  const srcFor = (e: EmbedOptions, page = embedPage) => embedUrl(window.location.href, onPage(page), e);
  const linkHref = () => {
    const u = new URL(window.location.href);
    u.search = `?${serializeState(pausedState())}`;
    u.hash = '';
    return u.toString();
  };
  // The iframe's title names the page it shows.
  const embedTitle = t.embedTitles[isEmbedPage(embedPage) ? embedPage : 'simulator'];
  const codeFor = (s: string, id: EmbedPresetId) => embedSnippet({ src: s, title: embedTitle, preset: presetOf(id) });
  const change = (next: EmbedOptions, page = embedPage) => {
    setEmbed(next);
    setEmbedPage(page);
    if (src !== null) setSrc(srcFor(next, page));
  };
  const offered = pageEmbedOptions(embedPage);
  const togglePanel = (p: EmbedPanel, on: boolean) =>
    change({ ...embed, panels: toggled(offered.panels, embed.panels, p, on) });
  const toggleLock = (p: LockableParam, on: boolean) =>
    change({ ...embed, locked: toggled(offered.locks, embed.locked, p, on) });
  const choosePage = (page: Page) => change(forPage(embed, page), page);

  // The offline file has no embed page beside it and no address anyone else can open: say so, offer no embed.
  if (isOfflineFile(pageHref))
    return (
      <div className="share-panel">
        <p className="note note-warning" data-testid="offline-share">
          {t.offlineShare}
        </p>
        <div className="share-buttons">
          <button type="button" className="btn btn-small" onClick={() => void copy(linkHref())}>
            {t.copyLocalLink}
          </button>
        </div>
        <p className="status-line" role="status" aria-live="polite">
          {status}
        </p>
        {shown ? <ShareText value={shown} label={t.sectionShare} rows={3} /> : null}
      </div>
    );

  return (
    <div className="share-panel">
      <div className="share-buttons">
        <button type="button" className="btn btn-small" onClick={() => void copy(linkHref())}>
          {t.copyLink}
        </button>
        <button type="button" className="btn btn-small" onClick={() => void copy(codeFor(srcFor(embed), presetId))}>
          {t.copyEmbed}
        </button>
      </div>
      <details className="embed-options" onToggle={(e) => setSrc(e.currentTarget.open ? srcFor(embed) : null)}>
        <summary>{t.embedGenerator}</summary>
        {src !== null ? (
          <Suspense fallback={null}>
            <EmbedGenerator
              embed={embed}
              page={embedPage}
              pages={EMBED_PAGES.map((p) => ({ value: p, label: pageLabel(p) }))}
              onPage={choosePage}
              presetId={presetId}
              src={src}
              code={codeFor(src, presetId)}
              onPreset={setPresetId}
              onPanel={togglePanel}
              onLock={toggleLock}
            />
          </Suspense>
        ) : null}
      </details>
      <p className="status-line" role="status" aria-live="polite">
        {status}
      </p>
      {shown ? <ShareText value={shown} label={t.sectionShare} rows={3} /> : null}
    </div>
  );
}

/**
 * Share link and embed code. The embed generator (opened on demand) chooses the size preset, the panels and
 * the locks, shows a live preview and the snippet; the copy buttons show the text when the clipboard fails.
 */
export const SharePanel = memo(SharePanelImpl);
