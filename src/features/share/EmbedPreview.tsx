import { useRef } from 'react';
import type { EmbedPreset } from './embedSnippet';
import { useElementSize } from '../../shared/hooks/useElementSize';

/** Props of EmbedPreview: the widget's URL, the frame's size preset and the frame's accessible title. */
export interface EmbedPreviewProps {
  src: string;
  preset: EmbedPreset;
  title: string;
}

/**
 * The embed as a host page would show it: an iframe of embed.html at the preset's CSS pixel size, scaled down
 * (never up) to the panel's width so the layout inside is the real one. It is a picture of the embed, out of the
 * Tab order (its 22 controls are the widget's, not the generator's). No sandbox attribute: the frame is this
 * app's own page, and the snippet's allow-scripts allow-same-origin on a same-origin frame only makes Chromium
 * warn that it "can escape its sandboxing" on every preview; on a course page, another origin, it cannot.
 */
export function EmbedPreview({ src, preset, title }: EmbedPreviewProps) {
  const box = useRef<HTMLDivElement>(null);
  const { width } = useElementSize(box);
  const scale = width > 0 ? Math.min(1, width / preset.width) : 0;
  return (
    <div className="embed-preview" ref={box} style={{ height: Math.ceil(preset.height * scale) }}>
      {scale > 0 ? (
        <iframe
          src={src}
          title={title}
          tabIndex={-1}
          width={preset.width}
          height={preset.height}
          data-scale={scale.toFixed(4)}
          style={{ transform: `scale(${scale})` }}
        />
      ) : null}
    </div>
  );
}
