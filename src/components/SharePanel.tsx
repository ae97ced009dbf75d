import './SharePanel.css';
import { memo, useState } from 'react';
import type { AppState } from '../state/appState';
import type { EmbedOptions, EmbedPanel, LockableParam } from '../state/url';
import { EMBED_PANELS, embedCode, embedUrl, serializeState } from '../state/url';
import { copyText } from './clipboard';
import { useMessages } from './MessagesContext';
import { Toggle } from './Toggle';

/** Props of SharePanel: how to read the state to share when a copy button is pressed. */
export interface SharePanelProps {
  /** Returns the current state; read on click, so the panel does not re-render while the state changes. */
  getState: () => AppState;
}

const LENGTHS: LockableParam[] = ['r1', 'r2', 'r3', 'r4'];

function SharePanelImpl({ getState }: SharePanelProps) {
  const t = useMessages();
  const [embed, setEmbed] = useState<EmbedOptions>({ panels: ['controls', 'plots'], locked: [] });
  const [status, setStatus] = useState('');
  const [shown, setShown] = useState<string | null>(null);

  const linkHref = () => {
    const u = new URL(window.location.href);
    u.search = `?${serializeState({ ...getState(), playing: false })}`;
    u.hash = '';
    return u.toString();
  };
  const code = () => embedCode(embedUrl(window.location.href, { ...getState(), playing: false }, embed), t.embedTitle);
  const copy = async (text: string) => {
    const ok = await copyText(text);
    setStatus(ok ? t.copied : t.copyFailed);
    setShown(text);
  };
  const togglePanel = (p: EmbedPanel, on: boolean) =>
    setEmbed((e) => ({
      ...e,
      panels: on ? EMBED_PANELS.filter((x) => x === p || e.panels.includes(x)) : e.panels.filter((x) => x !== p),
    }));
  const toggleLock = (params: LockableParam[], on: boolean) =>
    setEmbed((e) => ({
      ...e,
      locked: on ? [...new Set([...e.locked, ...params])] : e.locked.filter((x) => !params.includes(x)),
    }));

  return (
    <div className="share-panel">
      <div className="share-buttons">
        <button type="button" className="btn btn-small" onClick={() => void copy(linkHref())}>
          {t.copyLink}
        </button>
        <button type="button" className="btn btn-small" onClick={() => void copy(code())}>
          {t.copyEmbed}
        </button>
      </div>
      <details className="embed-options">
        <summary>
          {t.embedPanels} / {t.embedLock}
        </summary>
        <fieldset className="checks">
          <legend>{t.embedPanels}</legend>
          {EMBED_PANELS.map((p) => (
            <Toggle
              key={p}
              label={t.panelNames[p]}
              checked={embed.panels.includes(p)}
              onChange={(v) => togglePanel(p, v)}
            />
          ))}
        </fieldset>
        <fieldset className="checks">
          <legend>{t.embedLock}</legend>
          <Toggle
            label={t.lockLengths}
            checked={LENGTHS.every((p) => embed.locked.includes(p))}
            onChange={(v) => toggleLock(LENGTHS, v)}
          />
          <Toggle
            label={t.lockAngle}
            checked={embed.locked.includes('theta2')}
            onChange={(v) => toggleLock(['theta2'], v)}
          />
        </fieldset>
      </details>
      <p className="status-line" role="status" aria-live="polite">
        {status}
      </p>
      {shown ? (
        <textarea
          className="share-text"
          readOnly
          value={shown}
          aria-label={t.sectionShare}
          rows={3}
          onFocus={(e) => e.currentTarget.select()}
        />
      ) : null}
    </div>
  );
}

/** Share link and embed code: choose the embed's panels and locks, copy; shows the text when the clipboard fails. */
export const SharePanel = memo(SharePanelImpl);
