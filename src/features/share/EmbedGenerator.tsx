import type { EmbedPresetId } from './embedSnippet';
import { DEFAULT_EMBED_PRESET, EMBED_PRESETS } from './embedSnippet';
import type { Page } from '../../shared/state/appState';
import type { EmbedOptions, EmbedPanel, LockableParam } from '../../shared/url/url';
import { pageEmbedOptions } from '../../shared/url/url';
import { EmbedPreview } from './EmbedPreview';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { Segmented } from '../../shared/ui/Segmented';
import { Toggle } from '../../shared/ui/Toggle';
import { ShareText } from './ShareText';

/** Props of EmbedGenerator: the chosen options, the widget URL and snippet for them, and how to change them. */
export interface EmbedGeneratorProps {
  embed: EmbedOptions;
  /** The page the embed shows, the pages that embed (named as their tabs) and how to choose one. */
  page: Page;
  pages: readonly { value: Page; label: string }[];
  onPage: (page: Page) => void;
  presetId: EmbedPresetId;
  /** The embed URL for the current state and options (the preview's src). */
  src: string;
  /** The snippet for src and the preset (embedSnippet). */
  code: string;
  onPreset: (id: EmbedPresetId) => void;
  onPanel: (panel: EmbedPanel, on: boolean) => void;
  onLock: (param: LockableParam, on: boolean) => void;
}

/**
 * The Share panel's embed generator: the page, size presets, the page's panels and locks (PAGE_EMBEDS), a live
 * scaled preview and the snippet.
 */
export function EmbedGenerator(props: EmbedGeneratorProps) {
  const { embed, page, pages, onPage, presetId, src, code, onPreset, onPanel, onLock } = props;
  const t = useMessages();
  const preset = EMBED_PRESETS.find((p) => p.id === presetId) ?? DEFAULT_EMBED_PRESET;
  const offered = pageEmbedOptions(page);
  return (
    <div className="embed-generator">
      <Segmented legend={t.embedPage} value={page} options={pages} onChange={onPage} />
      <Segmented
        legend={t.embedSize}
        value={presetId}
        options={EMBED_PRESETS.map((p) => ({ value: p.id, label: t.embedPresetNames[p.id] }))}
        onChange={onPreset}
      />
      <fieldset className="checks">
        <legend>{t.embedPanels}</legend>
        {offered.panels.map((p) => (
          <Toggle key={p} label={t.panelNames[p]} checked={embed.panels.includes(p)} onChange={(v) => onPanel(p, v)} />
        ))}
      </fieldset>
      <fieldset className="checks">
        <legend>{t.embedLock}</legend>
        {offered.locks.map((p) => (
          <Toggle key={p} label={t.lockNames[p]} checked={embed.locked.includes(p)} onChange={(v) => onLock(p, v)} />
        ))}
      </fieldset>
      <EmbedPreview src={src} preset={preset} title={t.embedPreview} />
      <p className="embed-preview-note">{t.embedPreviewNote}</p>
      <ShareText value={code} label={t.embedCodeLabel} rows={4} />
    </div>
  );
}
