import { describe, expect, it } from 'vitest';
import type { Messages } from '../../../src/shared/i18n/messages';
import { messagesEn as appEn } from '../../../src/shared/i18n/messagesEn';
import { messagesZhTw as appZhTw } from '../../../src/shared/i18n/messagesZhTw';
import type { LabMessages } from '../../../src/features/lab/labMessages';
import { labMessagesEn } from '../../../src/features/lab/labMessagesEn';
import { labMessagesZhTw } from '../../../src/features/lab/labMessagesZhTw';

/** Every UI string of a language: the app's and the solver lab's. */
const messagesEn = { ...appEn, ...labMessagesEn };
const messagesZhTw = { ...appZhTw, ...labMessagesZhTw };

/**
 * The mechanism glossary, English to Traditional Chinese as taught in Taiwan (教育部 機構學 terms):
 * a zh-TW string must use one of `zh` wherever its English counterpart uses the English term.
 */
const GLOSSARY: ReadonlyArray<{ en: RegExp; zh: readonly string[] }> = [
  { en: /\bcrank/i, zh: ['曲柄'] },
  { en: /rocker/i, zh: ['搖桿'] },
  { en: /\bcoupler\b/i, zh: ['耦', '連桿', '連接桿'] },
  { en: /\bground\b/i, zh: ['機架', '固定桿'] },
  { en: /\bdead cent(re|er)/i, zh: ['死點'] },
  { en: /\btoggle/i, zh: ['肘節', '死點'] },
  { en: /\btransmission angle/i, zh: ['傳動角'] },
  { en: /\btime ratio/i, zh: ['急回比'] },
  { en: /\binstant(aneous)? cent(re|er)/i, zh: ['瞬心'] },
  { en: /\bangular velocity/i, zh: ['角速度'] },
  { en: /\bangular acceleration/i, zh: ['角加速度'] },
  { en: /\bchange point/i, zh: ['變點'] },
  { en: /\bparallelogram/i, zh: ['平行四邊形'] },
  { en: /\bbranch/i, zh: ['分支'] },
  { en: /\bclockwise/i, zh: ['時針'] },
];

/** Exact terms for named messages, including pairs that a swap must break (Open/Crossed, cw/ccw, ...). */
const TERMS: ReadonlyArray<{
  key: string;
  pick: (m: Messages & LabMessages) => string;
  en: RegExp;
  zh: string;
  notZh?: string[];
}> = [
  { key: 'branchOpen', pick: (m) => m.branchOpen, en: /^Open$/, zh: '開放', notZh: ['交叉'] },
  { key: 'branchCrossed', pick: (m) => m.branchCrossed, en: /^Crossed$/, zh: '交叉', notZh: ['開放'] },
  { key: 'ccw', pick: (m) => m.ccw, en: /^Counter-clockwise$/, zh: '逆時針', notZh: ['順時針'] },
  { key: 'cw', pick: (m) => m.cw, en: /^Clockwise$/, zh: '順時針', notZh: ['逆時針'] },
  { key: 'types.crank-rocker', pick: (m) => m.types['crank-rocker'], en: /^Crank-rocker$/, zh: '曲柄搖桿' },
  {
    key: 'types.double-crank',
    pick: (m) => m.types['double-crank'],
    en: /^Double crank/,
    zh: '雙曲柄',
    notZh: ['搖桿'],
  },
  {
    key: 'types.double-rocker',
    pick: (m) => m.types['double-rocker'],
    en: /^Double rocker/,
    zh: '雙搖桿',
    notZh: ['曲柄'],
  },
  {
    key: 'types.triple-rocker',
    pick: (m) => m.types['triple-rocker'],
    en: /^Triple rocker/,
    zh: '三搖桿',
    notZh: ['曲柄', '雙'],
  },
  { key: 'types.change-point', pick: (m) => m.types['change-point'], en: /^Change point/, zh: '變點' },
  { key: 'types.cannot-assemble', pick: (m) => m.types['cannot-assemble'], en: /assemble/, zh: '無法組裝' },
  { key: 'fieldLabels.r1', pick: (m) => m.fieldLabels.r1, en: /^r1 ground/, zh: '機架', notZh: ['曲柄', '搖桿'] },
  { key: 'fieldLabels.r2', pick: (m) => m.fieldLabels.r2, en: /^r2 crank/, zh: '曲柄', notZh: ['搖桿', '機架'] },
  { key: 'fieldLabels.r3', pick: (m) => m.fieldLabels.r3, en: /^r3 coupler/, zh: '耦桿', notZh: ['曲柄', '搖桿'] },
  { key: 'fieldLabels.r4', pick: (m) => m.fieldLabels.r4, en: /^r4 rocker/, zh: '搖桿', notZh: ['曲柄', '機架'] },
  {
    key: 'fieldLabels.omega2',
    pick: (m) => m.fieldLabels.omega2,
    en: /^ω2 .*angular velocity/,
    zh: '角速度',
    notZh: ['角加速度'],
  },
  { key: 'fieldLabels.alpha2', pick: (m) => m.fieldLabels.alpha2, en: /^α2 .*angular acceleration/, zh: '角加速度' },
  { key: 'fieldLabels.muBandLo', pick: (m) => m.fieldLabels.muBandLo, en: /lower/, zh: '下限', notZh: ['上限'] },
  { key: 'fieldLabels.muBandHi', pick: (m) => m.fieldLabels.muBandHi, en: /upper/, zh: '上限', notZh: ['下限'] },
  { key: 'transmissionAngle', pick: (m) => m.transmissionAngle, en: /^Transmission angle/, zh: '傳動角' },
  { key: 'stepBack', pick: (m) => m.stepBack, en: /^Step back$/, zh: '後退', notZh: ['前進'] },
  { key: 'stepForward', pick: (m) => m.stepForward, en: /^Step forward$/, zh: '前進', notZh: ['後退'] },
  { key: 'play', pick: (m) => m.play, en: /^Play$/, zh: '播放', notZh: ['暫停'] },
  { key: 'pause', pick: (m) => m.pause, en: /^Pause$/, zh: '暫停', notZh: ['播放'] },
  { key: 'zoomIn', pick: (m) => m.zoomIn, en: /^Zoom in$/, zh: '放大', notZh: ['縮小'] },
  { key: 'zoomOut', pick: (m) => m.zoomOut, en: /^Zoom out$/, zh: '縮小', notZh: ['放大'] },
  { key: 'grashofYes', pick: (m) => m.grashofYes, en: /^Grashof/, zh: '符合', notZh: ['非'] },
  { key: 'grashofNo', pick: (m) => m.grashofNo, en: /^Non-Grashof/, zh: '非' },
  { key: 'nrContinuation', pick: (m) => m.nrContinuation, en: /^Continuation$/, zh: '延續', notZh: ['冷'] },
  { key: 'nrCold', pick: (m) => m.nrCold, en: /^Cold start$/, zh: '冷啟動', notZh: ['延續'] },
  { key: 'plotSeparate', pick: (m) => m.plotSeparate, en: /^Separate$/, zh: '分開', notZh: ['合併'] },
  { key: 'plotTogether', pick: (m) => m.plotTogether, en: /^Together$/, zh: '合併', notZh: ['分開'] },
  { key: 'chartTheta3', pick: (m) => m.chartTheta3, en: /^θ3/, zh: 'θ3', notZh: ['θ4'] },
  { key: 'chartTheta4', pick: (m) => m.chartTheta4, en: /^θ4/, zh: 'θ4', notZh: ['θ3'] },
  { key: 'presetNames.dragLink', pick: (m) => m.presetNames.dragLink, en: /double crank/, zh: '雙曲柄' },
  { key: 'presetNames.doubleRocker', pick: (m) => m.presetNames.doubleRocker, en: /double rocker/i, zh: '雙搖桿' },
  { key: 'presetNames.tripleRocker', pick: (m) => m.presetNames.tripleRocker, en: /triple rocker/i, zh: '三搖桿' },
  { key: 'presetNames.nearToggle', pick: (m) => m.presetNames.nearToggle, en: /crank-rocker/i, zh: '曲柄搖桿' },
  { key: 'labStatusDone', pick: (m) => m.labStatusDone, en: /^Finished/, zh: '完成', notZh: ['取消', '執行中'] },
  { key: 'labStatusCancelled', pick: (m) => m.labStatusCancelled, en: /^Cancelled/, zh: '取消', notZh: ['完成'] },
  { key: 'urlNoticeDismiss', pick: (m) => m.urlNoticeDismiss, en: /^Dismiss$/, zh: '關閉' },
];

/** Every string of a messages object by dotted path; functions are called with placeholder arguments. */
function leaves(o: unknown, path = ''): Map<string, string> {
  const out = new Map<string, string>();
  if (typeof o === 'string') out.set(path, o);
  else if (typeof o === 'function') {
    try {
      const s = (o as (...a: unknown[]) => unknown)('‹1›', '‹2›', '‹3›', '‹4›');
      if (typeof s === 'string') out.set(path, s);
    } catch {
      // Functions that take objects (fieldError) are checked by their own tests.
    }
  } else if (o && typeof o === 'object')
    for (const [k, v] of Object.entries(o)) for (const [p, s] of leaves(v, path ? `${path}.${k}` : k)) out.set(p, s);
  return out;
}

describe('zh-TW glossary', () => {
  it.each(TERMS.map((x) => [x.key, x] as const))('%s uses the right term in both languages', (_key, term) => {
    expect(term.pick(messagesEn)).toMatch(term.en);
    const zh = term.pick(messagesZhTw);
    expect(zh).toContain(term.zh);
    for (const bad of term.notZh ?? []) expect(zh).not.toContain(bad);
  });

  it('uses the glossary term wherever the English string uses the English term', () => {
    const en = leaves(messagesEn);
    const zh = leaves(messagesZhTw);
    const misses: string[] = [];
    for (const [path, text] of en) {
      const other = zh.get(path) ?? '';
      for (const g of GLOSSARY)
        if (g.en.test(text) && !g.zh.some((w) => other.includes(w))) misses.push(`${path}: ${g.en} -> ${g.zh}`);
    }
    expect(misses).toEqual([]);
  });

  it('checks a real share of the strings (the walk finds the domain terms)', () => {
    const en = [...leaves(messagesEn).values()];
    for (const g of GLOSSARY.filter((x) => !/dead|time ratio|instant|angular velocity|toggle/.test(x.en.source)))
      expect(
        en.some((s) => g.en.test(s)),
        String(g.en),
      ).toBe(true);
  });
});
