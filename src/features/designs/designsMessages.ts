import type { Locale } from '../../shared/state/appState';
import { messageModule } from '../../shared/i18n/messageModule';
import type { BadField } from './designFile';

/** Strings of the design bar (undo, redo, save, open, recent), its notices and the restore offer. */
export interface DesignsMessages {
  /** The bar's group name. */
  barLabel: string;
  undo: string;
  redo: string;
  /** Tooltips with the keys. */
  undoKeys: string;
  redoKeys: string;
  /** The buttons' accessible names and, on wide screens, their text. */
  save: string;
  open: string;
  /** Tooltips of Save and Open. */
  saveTitle: string;
  openTitle: string;
  /** The recent designs menu: its button, its list's name, and one entry's accessible name. */
  recent: string;
  recentLabel: string;
  recentItem: (name: string, when: string) => string;
  /** Notices after Save and Open. */
  saved: (fileName: string) => string;
  opened: (name: string) => string;
  /** A refused file: the file's name and why; every one ends saying the current work is kept. */
  notJson: (file: string) => string;
  notObject: (file: string) => string;
  newer: (file: string, version: number, newest: number) => string;
  badFields: (file: string, fields: readonly BadField[]) => string;
  unreadable: (file: string) => string;
  /** The restore offer: its text (the session's name and time), its buttons. */
  restoreText: (name: string, when: string) => string;
  restore: string;
  dismiss: string;
  /** A notice's close button. */
  closeNotice: string;
}

/** Most bad fields a message names one by one; the rest are counted. */
export const MAX_FIELDS_NAMED = 4;

function fieldList(
  fields: readonly BadField[],
  item: (f: BadField) => string,
  more: (n: number) => string,
  sep: string,
) {
  const named = fields.slice(0, MAX_FIELDS_NAMED).map(item);
  if (fields.length > MAX_FIELDS_NAMED) named.push(more(fields.length - MAX_FIELDS_NAMED));
  return named.join(sep);
}

const KEPT_EN = 'Your current work is unchanged.';

const EN: DesignsMessages = {
  barLabel: 'Design file and history',
  undo: 'Undo',
  redo: 'Redo',
  undoKeys: 'Undo (Ctrl+Z)',
  redoKeys: 'Redo (Ctrl+Shift+Z or Ctrl+Y)',
  save: 'Save design',
  open: 'Open design',
  saveTitle: 'Save the design as a .fourbar.json file',
  openTitle: 'Open a .fourbar.json design file',
  recent: 'Recent',
  recentLabel: 'Recent designs',
  recentItem: (name, when) => `${name}, ${when}`,
  saved: (file) => `Saved ${file}.`,
  opened: (name) => `Opened “${name}”.`,
  notJson: (file) => `“${file}” was not opened: it is not JSON. ${KEPT_EN}`,
  notObject: (file) => `“${file}” was not opened: it is not a design file. ${KEPT_EN}`,
  newer: (file, v, newest) =>
    `“${file}” was not opened: it was saved by a newer version of the app (file version ${v}; this app reads up to ${newest}). ${KEPT_EN}`,
  badFields: (file, fields) =>
    `“${file}” was not opened: ${fieldList(
      fields,
      (f) => `${f.field} is ${f.value}: ${f.why}`,
      (n) => `and ${n} more`,
      '; ',
    )}. ${KEPT_EN}`,
  unreadable: (file) => `“${file}” could not be read. ${KEPT_EN}`,
  restoreText: (name, when) => `Your last session (${when ? `${name}, ${when}` : name}) was saved in this browser.`,
  restore: 'Restore last session',
  dismiss: 'Dismiss',
  closeNotice: 'Close',
};

const KEPT_ZH = '目前的工作未變更。';

const ZH_TW: DesignsMessages = {
  barLabel: '設計檔與復原',
  undo: '復原',
  redo: '重做',
  undoKeys: '復原（Ctrl+Z）',
  redoKeys: '重做（Ctrl+Shift+Z 或 Ctrl+Y）',
  save: '儲存設計',
  open: '開啟設計',
  saveTitle: '將設計存成 .fourbar.json 檔',
  openTitle: '開啟 .fourbar.json 設計檔',
  recent: '最近',
  recentLabel: '最近的設計',
  recentItem: (name, when) => `${name}，${when}`,
  saved: (file) => `已儲存 ${file}。`,
  opened: (name) => `已開啟「${name}」。`,
  notJson: (file) => `未開啟「${file}」：它不是 JSON。${KEPT_ZH}`,
  notObject: (file) => `未開啟「${file}」：它不是設計檔。${KEPT_ZH}`,
  newer: (file, v, newest) =>
    `未開啟「${file}」：它由較新版本的程式儲存（檔案版本 ${v}；本程式最多讀取 ${newest}）。${KEPT_ZH}`,
  badFields: (file, fields) =>
    `未開啟「${file}」：${fieldList(
      fields,
      (f) => `${f.field} 為 ${f.value}：${f.why}`,
      (n) => `另有 ${n} 項`,
      '；',
    )}。${KEPT_ZH}`,
  unreadable: (file) => `無法讀取「${file}」。${KEPT_ZH}`,
  restoreText: (name, when) => `這個瀏覽器保存了你上次的工作階段（${when ? `${name}，${when}` : name}）。`,
  restore: '還原上次工作階段',
  dismiss: '略過',
  closeNotice: '關閉',
};

/** The design bar's strings in every language (small: both bundled). */
const designs = messageModule<DesignsMessages>(EN, { 'zh-TW': ZH_TW });

/** The design bar's strings in a language. */
export function designsMessages(locale: Locale): DesignsMessages {
  return designs.get(locale);
}

/** A time as the UI shows it in a language: date and time, short. */
export function shownTime(iso: string, locale: Locale): string {
  const d = new Date(iso);
  if (Number.isNaN(d.getTime())) return iso;
  return new Intl.DateTimeFormat(locale, { dateStyle: 'medium', timeStyle: 'short' }).format(d);
}
