import type { EmbedPresetId } from './embedSnippet';
import { DEFAULT_EMBED_PRESET, EMBED_PRESETS } from './embedSnippet';
import type { EmbedOptions, EmbedPanel, LockableParam } from '../../shared/url/url';
import { EMBED_PANELS, LOCKABLE_PARAMS } from '../../shared/url/url';
import { EmbedPreview } from './EmbedPreview';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { Segmented } from '../../shared/ui/Segmented';
import { Toggle } from '../../shared/ui/Toggle';
import { ShareText } from './ShareText';

/** Props of EmbedGenerator: the chosen options, the widget URL and snippet for them, and how to change them. */
export interface EmbedGeneratorProps {
  embed: EmbedOptions;
  presetId: EmbedPresetId;
  /** The embed URL for the current state and options (the preview's src). */
  src: string;
  /** The snippet for src and the preset (embedSnippet). */
  code: string;
  onPreset: (id: EmbedPresetId) => void;
  onPanel: (panel: EmbedPanel, on: boolean) => void;
  onLock: (param: LockableParam, on: boolean) => void;
}

/** The Share panel's embed generator: size presets, panels, locks, a live scaled preview and the snippet. */
export function EmbedGenerator({ embed, presetId, src, code, onPreset, onPanel, onLock }: EmbedGeneratorProps) {
  const t = useMessages();
  const preset = EMBED_PRESETS.find((p) => p.id === presetId) ?? DEFAULT_EMBED_PRESET;
  return (
    <div className="embed-generator">
      <Segmented
        legend={t.embedSize}
        value={presetId}
        options={EMBED_PRESETS.map((p) => ({ value: p.id, label: t.embedPresetNames[p.id] }))}
        onChange={onPreset}
      />
      <fieldset className="checks">
        <legend>{t.embedPanels}</legend>
        {EMBED_PANELS.map((p) => (
          <Toggle key={p} label={t.panelNames[p]} checked={embed.panels.includes(p)} onChange={(v) => onPanel(p, v)} />
        ))}
      </fieldset>
      <fieldset className="checks">
        <legend>{t.embedLock}</legend>
        {LOCKABLE_PARAMS.map((p) => (
          <Toggle key={p} label={t.lockNames[p]} checked={embed.locked.includes(p)} onChange={(v) => onLock(p, v)} />
        ))}
      </fieldset>
      <EmbedPreview src={src} preset={preset} title={t.embedPreview} />
      <p className="embed-preview-note">{t.embedPreviewNote}</p>
      <ShareText value={code} label={t.embedCodeLabel} rows={4} />
    </div>
  );
}
