import './PhoneBar.css';
import { useState } from 'react';
import type { Locale } from '../../../shared/state/appState';
import { DRAG_HINT_STORAGE_KEY, readStorage, writeStorage } from '../../../shared/storage';
import { useMediaQuery } from '../../../shared/hooks/useMediaQuery';
import { PHONE_MEDIA } from '../../../shared/theme/tokens';
import { phoneMessages } from './phoneMessages';

/** Props of DragHint: the language. */
export interface DragHintProps {
  locale: Locale;
}

/**
 * The phone layout's first-use hint over the canvas: the joints can be dragged. Shown on a phone until dismissed,
 * then never again on this device (localStorage); where storage is unavailable, until dismissed in this visit.
 * The full app's simulator page only: the embeds leave it out.
 */
export function DragHint({ locale }: DragHintProps) {
  const phone = useMediaQuery(PHONE_MEDIA);
  const [shown, setShown] = useState(() => readStorage(DRAG_HINT_STORAGE_KEY) !== '1');
  if (!phone || !shown) return null;
  const p = phoneMessages(locale);
  return (
    <div className="drag-hint" role="note">
      <span>{p.dragHint}</span>
      <button
        type="button"
        className="btn btn-small"
        onClick={() => {
          writeStorage(DRAG_HINT_STORAGE_KEY, '1');
          setShown(false);
        }}
      >
        {p.dragHintDismiss}
      </button>
    </div>
  );
}
