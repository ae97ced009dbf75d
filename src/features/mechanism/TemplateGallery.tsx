import { useLayoutEffect, useRef } from 'react';
import { MECHANISM_TEMPLATES } from '../../mechanism';
import { fitView } from '../../shared/canvas/view';
import { sizeCanvas } from '../../shared/canvas/sizeCanvas';
import type { MechTemplateKey } from '../../shared/state/slices/mechSlice';
import { MECH_TEMPLATE_KEYS } from '../../shared/state/slices/mechSlice';
import { drawMechanism, pictureBounds } from './drawMechanism';
import { drawnPose } from './mechPose';

const THUMB_W = 96;
const THUMB_H = 56;

/** A template's thumbnail: its drawn configuration, fitted, without grid or names. */
function Thumb({ template }: { template: MechTemplateKey }) {
  const ref = useRef<HTMLCanvasElement>(null);
  useLayoutEffect(() => {
    const sized = ref.current && sizeCanvas(ref.current, THUMB_W, THUMB_H);
    if (!sized) return;
    const spec = MECHANISM_TEMPLATES[template].spec;
    const pose = drawnPose(spec);
    const pic = { spec, pose, traces: [], slideRange: {}, selected: null, arrows: [], faint: false, compact: true };
    drawMechanism(sized.ctx, pic, fitView(pictureBounds(pic), THUMB_W, THUMB_H, { zoom: 1, panX: 0, panY: 0 }, 0.12));
  }, [template]);
  return <canvas ref={ref} className="mech-thumb" width={THUMB_W} height={THUMB_H} aria-hidden="true" />;
}

/** Props of TemplateGallery: the template open, whether it was edited, what opening one does, and the names. */
export interface TemplateGalleryProps {
  current: MechTemplateKey;
  edited: boolean;
  onOpen: (template: MechTemplateKey) => void;
  names: Record<string, string>;
  label: string;
}

/** The templates as buttons with thumbnails and names; the open one is pressed (aria-pressed). */
export function TemplateGallery({ current, edited, onOpen, names, label }: TemplateGalleryProps) {
  return (
    <ul className="mech-gallery" aria-label={label}>
      {MECH_TEMPLATE_KEYS.map((key) => (
        <li key={key}>
          <button
            type="button"
            className="mech-template"
            aria-pressed={key === current && !edited}
            data-template={key}
            onClick={() => onOpen(key)}
          >
            <Thumb template={key} />
            <span className="mech-template-name">{names[key] ?? key}</span>
          </button>
        </li>
      ))}
    </ul>
  );
}
