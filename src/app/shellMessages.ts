import type { Locale } from '../shared/state/appState';
import { messageModule } from '../shared/i18n/messageModule';

/** Strings of the app shell (skip link, landmarks, the canvas hint): the shell's own message module. */
export interface ShellMessages {
  /** The skip link's text. */
  skipToMain: string;
  /** Names of the two side landmarks of the full app: the controls and the results column. */
  controlsLabel: string;
  resultsLabel: string;
  /** The canvas's control hint; crank and coupler say whether A and P can be dragged (not locked). */
  canvasHint: (movable: { crank: boolean; coupler: boolean }) => string;
}

const EN: ShellMessages = {
  skipToMain: 'Skip to main content',
  controlsLabel: 'Controls',
  resultsLabel: 'Results, export and share',
  canvasHint: ({ crank, coupler }) => {
    const drag = [crank ? 'A to turn the crank' : '', coupler ? 'P to move the coupler point' : '', 'elsewhere to pan']
      .filter(Boolean)
      .join(', ');
    const keys = crank ? '← → turn the crank (Shift: 10°), ' : '';
    return `Drag ${drag}; pinch to zoom. Keys: ${keys}+ − zoom, 0 resets the view.`;
  },
};

const ZH_TW: ShellMessages = {
  skipToMain: '跳到主要內容',
  controlsLabel: '控制項',
  resultsLabel: '結果、匯出與分享',
  canvasHint: ({ crank, coupler }) => {
    const drag = [crank ? ' A 轉動曲柄' : '', coupler ? ' P 移動耦點' : '', '其他地方平移'].filter(Boolean).join('、');
    const keys = crank ? '← → 轉動曲柄（Shift：10°），' : '';
    return `拖曳${drag}；雙指縮放。按鍵：${keys}+ − 縮放，0 重設視圖。`;
  },
};

/** The shell's strings in every language (small: both bundled). */
const shell = messageModule<ShellMessages>(EN, { 'zh-TW': ZH_TW });

/** The shell's strings in a language. */
export function shellMessages(locale: Locale): ShellMessages {
  return shell.get(locale);
}
