import './DesignBar.css';
import { useEffect, useRef, useState } from 'react';
import type { Dispatch } from 'react';
import type { Action, AppState } from '../../shared/state/appState';
import { Icon } from '../../shared/ui/Icon';
import type { IconName } from '../../shared/ui/Icon';
import { DESIGN_FILE_EXTENSION } from './designFile';
import { designsMessages, shownTime } from './designsMessages';
import { DesignNotices } from './DesignNotices';
import type { RecentDesign } from './recentDesigns';
import { useDesignFiles } from './useDesignFiles';
import { useUndoKeys } from './useUndoKeys';

/** Props of DesignBar: the state, its dispatcher, and the history's undo and redo. */
export interface DesignBarProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  undo: () => void;
  redo: () => void;
  canUndo: boolean;
  canRedo: boolean;
}

interface BarButtonProps {
  icon: IconName;
  label: string;
  title: string;
  onClick: () => void;
  disabled?: boolean;
  /** Show only the icon at every width (the label stays the accessible name). */
  iconOnly?: boolean;
}

/** A button of the bar: an icon and its label (hidden on narrow screens, or always when iconOnly; it stays the name). */
function BarButton({ icon, label, title, onClick, disabled = false, iconOnly = false }: BarButtonProps) {
  return (
    <button
      type="button"
      className={`design-btn${iconOnly ? ' icon-only' : ''}`}
      title={title}
      onClick={onClick}
      disabled={disabled}
    >
      <Icon name={icon} />
      <span className="design-btn-label">{label}</span>
    </button>
  );
}

interface RecentMenuProps {
  recent: readonly RecentDesign[];
  label: string;
  listLabel: string;
  /** An entry's accessible name, and its time as shown. */
  item: (d: RecentDesign) => string;
  time: (d: RecentDesign) => string;
  onOpen: (d: RecentDesign) => void;
}

/** The recent designs as a disclosure menu; Escape or a click outside closes it. */
function RecentMenu({ recent, label, listLabel, item, time, onOpen }: RecentMenuProps) {
  const [open, setOpen] = useState(false);
  const root = useRef<HTMLDivElement>(null);
  useEffect(() => {
    if (!open) return;
    const outside = (e: PointerEvent) => {
      if (!root.current?.contains(e.target as Node)) setOpen(false);
    };
    const escape = (e: KeyboardEvent) => {
      if (e.key === 'Escape') setOpen(false);
    };
    document.addEventListener('pointerdown', outside);
    document.addEventListener('keydown', escape);
    return () => {
      document.removeEventListener('pointerdown', outside);
      document.removeEventListener('keydown', escape);
    };
  }, [open]);
  if (recent.length === 0) return null;
  return (
    <div className="recent-menu" ref={root}>
      <button
        type="button"
        className="design-btn icon-only"
        aria-expanded={open}
        aria-controls="recent-designs"
        title={listLabel}
        onClick={() => setOpen(!open)}
      >
        <Icon name="recent" />
        <span className="design-btn-label">{label}</span>
      </button>
      {open ? (
        <ul className="recent-list" id="recent-designs" aria-label={listLabel}>
          {recent.map((d) => (
            <li key={d.name}>
              <button
                type="button"
                aria-label={item(d)}
                onClick={() => {
                  setOpen(false);
                  onOpen(d);
                }}
              >
                <span className="recent-name">{d.name}</span>
                <span className="recent-time">{time(d)}</span>
              </button>
            </li>
          ))}
        </ul>
      ) : null}
    </div>
  );
}

/**
 * The top bar's design group: Undo and Redo (with Ctrl/Cmd+Z, Ctrl/Cmd+Shift+Z and Ctrl+Y outside text fields),
 * Save design (a `.fourbar.json` download), Open design (a file chooser), the recent designs, and the notices:
 * what was saved or opened, why a file was refused, and the offer to restore the last session.
 */
export function DesignBar({ state, dispatch, undo, redo, canUndo, canRedo }: DesignBarProps) {
  const locale = state.shell.locale;
  const t = designsMessages(locale);
  const files = useDesignFiles(state, dispatch, t);
  const input = useRef<HTMLInputElement>(null);
  useUndoKeys(undo, redo);
  return (
    <>
      <div className="design-bar" role="group" aria-label={t.barLabel}>
        <BarButton icon="undo" label={t.undo} title={t.undoKeys} onClick={undo} disabled={!canUndo} iconOnly />
        <BarButton icon="redo" label={t.redo} title={t.redoKeys} onClick={redo} disabled={!canRedo} iconOnly />
        <BarButton icon="save" label={t.save} title={t.saveTitle} onClick={files.save} />
        <BarButton icon="open" label={t.open} title={t.openTitle} onClick={() => input.current?.click()} />
        <input
          ref={input}
          type="file"
          accept={`${DESIGN_FILE_EXTENSION},.json,application/json`}
          hidden
          onChange={(e) => {
            const file = e.target.files?.[0];
            // Cleared, so choosing the same file again still reads it.
            e.target.value = '';
            if (file) void files.openFile(file);
          }}
        />
        <RecentMenu
          recent={files.recent}
          label={t.recent}
          listLabel={t.recentLabel}
          item={(d) => t.recentItem(d.name, shownTime(d.at, locale))}
          time={(d) => shownTime(d.at, locale)}
          onOpen={files.openRecent}
        />
      </div>
      <DesignNotices
        notice={files.notice}
        onClose={files.closeNotice}
        offer={files.offer}
        onRestore={files.restore}
        onDismissOffer={files.dismissOffer}
        t={t}
        locale={locale}
      />
    </>
  );
}
