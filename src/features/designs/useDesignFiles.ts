import { useCallback, useEffect, useState } from 'react';
import type { Dispatch } from 'react';
import type { Action, AppState } from '../../shared/state/appState';
import { downloadBlob } from '../../shared/canvas/download';
import { fileStem } from '../../shared/fileNames';
import { useLatest } from '../../shared/hooks/useLatest';
import { AUTOSAVE_STORAGE_KEY, readStorage } from '../../shared/storage';
import type { RestoreOffer } from './autosave';
import { restoreOffer } from './autosave';
import type { DesignFileError } from './designFile';
import {
  DESIGN_FILE_VERSION,
  designFileName,
  designNameOf,
  readDesignFile,
  taskName,
  writeDesignFile,
} from './designFile';
import type { Page } from '../../shared/state/slices/shellSlice';
import type { DesignsMessages } from './designsMessages';
import type { RecentDesign } from './recentDesigns';
import { readRecent, rememberRecent } from './recentDesigns';
import { useAutosave } from './useAutosave';

/** A notice of the design bar: a status (saved, opened) or an alert (a refused file). */
export interface DesignNotice {
  kind: 'status' | 'alert';
  text: string;
}

/** How long a status notice (saved, opened) stays, ms; an alert stays until it is closed. */
export const STATUS_NOTICE_MS = 5000;

/** The message of a refused file. */
export function fileErrorText(t: DesignsMessages, file: string, error: DesignFileError): string {
  switch (error.kind) {
    case 'notJson':
      return t.notJson(file);
    case 'notObject':
      return t.notObject(file);
    case 'newer':
      return t.newer(file, error.version, DESIGN_FILE_VERSION);
    case 'fields':
      return t.badFields(file, error.fields);
  }
}

/**
 * The design bar's work: the design's name (the last file opened or saved; else the lengths' file stem), Save
 * (a download), Open (a File) and the recent designs, the notices they give, the autosave and the restore offer
 * read once at start. An opened or restored design replaces the state in one undoable step.
 */
export function useDesignFiles(state: AppState, dispatch: Dispatch<Action>, t: DesignsMessages) {
  const [name, setName] = useState<string | null>(null);
  const [recent, setRecent] = useState<RecentDesign[]>(readRecent);
  const [notice, setNotice] = useState<DesignNotice | null>(null);
  const [offer, setOffer] = useState<RestoreOffer | null>(() =>
    restoreOffer(readStorage(AUTOSAVE_STORAGE_KEY), state, window.location.search),
  );
  const latest = useLatest(state);
  // On the synthesis page an unnamed design is named after its task.
  const shownName = name ?? taskName(state) ?? fileStem(state.design.linkage, state.design.branch);
  // An unnamed design is autosaved without a name, so a restored one keeps following its lengths.
  useAutosave(state, name ?? '');

  useEffect(() => {
    if (notice?.kind !== 'status') return;
    const id = setTimeout(() => setNotice(null), STATUS_NOTICE_MS);
    return () => clearTimeout(id);
  }, [notice]);

  const apply = useCallback(
    (next: AppState, designName: string, page: Page | null = null) => {
      // The reader's language and page stay, but a file of synthesis work opens on its page; everything else a file
      // holds comes from it.
      const shell = { ...latest.current.shell, page: page ?? latest.current.shell.page };
      dispatch({ type: 'replace', state: { ...next, shell } });
      setName(designName || null);
      setOffer(null);
    },
    [dispatch, latest],
  );

  const openText = useCallback(
    (text: string, fileName: string) => {
      const r = readDesignFile(text, latest.current);
      if (!r.ok) {
        setNotice({ kind: 'alert', text: fileErrorText(t, fileName, r.error) });
        return;
      }
      const designName = r.name || designNameOf(fileName);
      apply(r.state, designName, r.page);
      setRecent(rememberRecent({ name: designName, at: new Date().toISOString(), file: text }));
      setNotice({ kind: 'status', text: t.opened(designName) });
    },
    [apply, latest, t],
  );

  const openFile = useCallback(
    async (file: File) => {
      let text: string;
      try {
        text = await file.text();
      } catch {
        setNotice({ kind: 'alert', text: t.unreadable(file.name) });
        return;
      }
      openText(text, file.name);
    },
    [openText, t],
  );

  const openRecent = useCallback((d: RecentDesign) => openText(d.file, d.name), [openText]);

  const save = useCallback(() => {
    const text = writeDesignFile(latest.current, shownName, new Date());
    const fileName = designFileName(shownName);
    downloadBlob(new Blob([text], { type: 'application/json' }), fileName);
    setName(shownName);
    setRecent(rememberRecent({ name: shownName, at: new Date().toISOString(), file: text }));
    setNotice({ kind: 'status', text: t.saved(fileName) });
  }, [latest, shownName, t]);

  const restore = useCallback(() => {
    if (offer) apply(offer.state, offer.name);
  }, [apply, offer]);

  return {
    name: shownName,
    recent,
    notice,
    closeNotice: useCallback(() => setNotice(null), []),
    offer,
    restore,
    dismissOffer: useCallback(() => setOffer(null), []),
    save,
    openFile,
    openRecent,
  };
}
