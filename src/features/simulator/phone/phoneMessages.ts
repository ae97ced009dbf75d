import type { Locale } from '../../../shared/state/appState';
import { messageModule } from '../../../shared/i18n/messageModule';

/** Strings of the phone layout: its bar, the controls sheet's button and the first-use hint. */
export interface PhoneMessages {
  /** The bar's region name (Play, step, θ2 and the branch). */
  barLabel: string;
  /** The button that opens and closes the sheet of all the other controls. */
  allControls: string;
  /** The first-use hint over the canvas: the joints can be dragged. */
  dragHint: string;
  /** Its dismiss button. */
  dragHintDismiss: string;
}

const EN: PhoneMessages = {
  barLabel: 'Play and input angle',
  allControls: 'All controls',
  dragHint: 'Tip: drag joint A to turn the crank, or P to move the coupler point. Pinch to zoom.',
  dragHintDismiss: 'Got it',
};

const ZH_TW: PhoneMessages = {
  barLabel: '播放與輸入角',
  allControls: '全部控制項',
  dragHint: '提示：拖曳 A 點轉動曲柄，或拖曳 P 點移動耦點。雙指縮放。',
  dragHintDismiss: '知道了',
};

/** The phone layout's strings in every language (small: both bundled). */
const phone = messageModule<PhoneMessages>(EN, { 'zh-TW': ZH_TW });

/** The phone layout's strings in a language. */
export function phoneMessages(locale: Locale): PhoneMessages {
  return phone.get(locale);
}
