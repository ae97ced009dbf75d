import type { Messages } from './messages';

/** Traditional Chinese (Taiwan) UI strings. */
export const messagesZhTw: Messages = {
  htmlLang: 'zh-Hant-TW',
  appTitle: '四連桿機構實驗室',
  appSubtitle: '牛頓–拉夫森位置分析',
  language: '語言',
  languageNames: { en: 'English', 'zh-TW': '繁體中文' },

  sectionLinks: '桿長',
  sectionInput: '輸入角',
  sectionCoupler: '耦點 P',
  sectionAnimation: '動畫',
  sectionDisplay: '顯示',
  sectionExport: '匯出',
  sectionShare: '分享與嵌入',
  sectionAnalysis: '分析',
  sectionPlots: '圖表',

  fieldLabels: {
    r1: 'r1 固定桿（機架）',
    r2: 'r2 曲柄（輸入桿）',
    r3: 'r3 連接桿（耦桿）',
    r4: 'r4 搖桿（輸出桿）',
    theta2: 'θ2 輸入角（°）',
    couplerDistance: 'P 與 A 的距離',
    couplerAngle: 'P 相對 AB 的角度（°）',
    speed: '速度（°/幀）',
  },
  sliderSuffix: '滑桿',
  fieldShortNames: {
    r1: 'r1',
    r2: 'r2',
    r3: 'r3',
    r4: 'r4',
    theta2: 'θ2',
    couplerDistance: 'P 距離',
    couplerAngle: 'P 角度',
    speed: '速度',
  },
  fieldError: (e, f) => {
    const name = messagesZhTw.fieldShortNames[e.field];
    switch (e.kind) {
      case 'empty':
        return `${name}：請輸入數字。`;
      case 'notNumber':
        return `${name}：「${f.raw}」不是數字。`;
      case 'notPositive':
        return `${name} 必須大於 0，目前為 ${f.raw}。`;
      case 'negative':
        return `${name} 不可為負數，目前為 ${f.raw}。`;
      case 'tooSmall':
        return `${name}：${f.raw} 太小（至少 ${f.min}）。`;
      case 'tooLarge':
        return `${name}：${f.raw} 超出範圍（${f.min} 至 ${f.max}）。`;
    }
  },
  keepingLast: (v) => `保留上一個有效值 ${v}。`,
  locked: '已鎖定',

  branch: '組裝分支',
  branchOpen: '開放型',
  branchCrossed: '交叉型',
  play: '播放',
  pause: '暫停',
  direction: '方向',
  ccw: '逆時針',
  cw: '順時針',
  stepBack: '後退一步',
  stepForward: '前進一步',
  rockingNote: '輸入桿無法整圈轉動：在兩極限位置間來回擺動，並在極限處切換分支。',

  showGrid: '格線',
  showAngles: '角度標示',
  showGhost: '另一分支（虛影）',
  showTrace: '耦點曲線',
  samples: '每圈取樣數',

  preset: '預設機構',
  presetPlaceholder: '自訂機構',
  presetNames: {
    report: '報告案例 6-2-5-5',
    dragLink: '拖曳連桿（雙曲柄）',
    doubleRocker: 'Grashof 雙搖桿',
    tripleRocker: '三搖桿（非 Grashof）',
    parallelogram: '平行四邊形機構',
    nearToggle: '接近肘節的曲柄搖桿',
    chebyshevLambda: '契比雪夫 λ 機構',
    hoeckens: '霍肯斯直線機構',
  },

  grashofCheck: 'Grashof 判別',
  grashofYes: '符合 Grashof（S + L < P + Q）',
  grashofNo: '非 Grashof（S + L > P + Q）',
  grashofChangePoint: '變點（S + L = P + Q）',
  linkageType: '機構類型',
  types: {
    'crank-rocker': '曲柄搖桿',
    'double-crank': '雙曲柄（拖曳連桿）',
    'double-rocker': '雙搖桿',
    'change-point': '變點機構',
    'triple-rocker': '三搖桿',
    'cannot-assemble': '無法組裝',
  },
  barker: 'Barker 分類',
  inputRange: '輸入角 θ2 範圍',
  fullTurn: '整圈',
  noRange: '無',
  rangeInterval: (lo, hi) => `${lo}° 至 ${hi}°`,
  atTheta2: (t) => `θ2 = ${t}° 時`,
  nrIterations: 'NR 迭代次數',
  residual: '殘差 |f|',
  detJ: 'det J',
  status: '狀態',
  newtonStatus: { converged: '已收斂', singular: 'Jacobian 奇異', 'max-iterations': '達迭代上限' },
  pointStatus: { ok: '可組裝', unreachable: '無法組裝', singular: '奇異', failed: '失敗' },
  transmissionAngle: '傳動角 μ',
  cycleSummary: (ok, total, it) => `整圈：${total} 點中 ${ok} 點可組裝，NR 共迭代 ${it} 次`,
  solvingOnMainThread: '此處無法使用 Web Worker：改在主執行緒求解。',

  plotSeparate: '分開',
  plotTogether: '合併',
  plotLayout: '角度圖',
  nrStartLabel: 'NR 起始值',
  nrContinuation: '延續前一點',
  nrCold: '冷啟動',
  chartTheta3: 'θ3 對 θ2',
  chartTheta4: 'θ4 對 θ2',
  chartBoth: 'θ3、θ4 對 θ2',
  chartConvergence: (t) => `θ2 = ${t}° 的 NR 收斂`,
  axisTheta2: 'θ2（°）',
  axisTheta3: 'θ3（°）',
  axisTheta4: 'θ4（°）',
  axisAngle: '角度（°）',
  axisIteration: '迭代次數',
  axisResidual: '殘差 |f|（長度單位）',
  legendOtherBranch: '另一分支',
  angleFootnote:
    '角度單位為度，自機架線逆時針量起。θ2 為一整圈 0° 至 360°；θ3、θ4 與 μ 換算至 (−180°, 180°]。曲線中斷處表示機構無法組裝。',
  noConvergenceData: '此處無法組裝，沒有 NR 迭代。',

  canvasLabel: '連桿機構圖',
  cannotAssembleAt: (t) => `θ2 = ${t}° 時無法組裝`,
  cannotAssembleAny: '此機構在任何輸入角都無法組裝',
  reachableHint: (r) => `可達 θ2：${r}`,
  resetView: '重設視圖',
  zoomIn: '放大',
  zoomOut: '縮小',
  gridSpacing: (s) => `格距 ${s}`,
  jointLabels: { O2: 'O2', O4: 'O4', A: 'A', B: 'B', P: 'P' },

  exportSize: 'PNG 尺寸',
  sizeScreen: '螢幕',
  size2x: '2×',
  sizePrint: '300 DPI 列印',
  exportLinkage: '匯出連桿圖 PNG',
  exportTheta3: '匯出 θ3 圖 PNG',
  exportTheta4: '匯出 θ4 圖 PNG',
  exportBoth: '匯出 θ3、θ4 合併圖 PNG',
  exportConvergence: '匯出 NR 收斂圖 PNG',
  exportCsv: '匯出整圈資料 CSV',
  exportFailed: (r) => `匯出失敗：${r}`,

  copyLink: '複製連結',
  copyEmbed: '複製嵌入碼',
  copied: '已複製到剪貼簿。',
  copyFailed: '此處無法使用剪貼簿：請選取下方文字後自行複製。',
  embedPanels: '嵌入時顯示',
  embedLock: '嵌入時鎖定',
  panelNames: { controls: '控制項', info: '分析', plots: '圖表', export: '匯出' },
  lockLengths: '桿長',
  lockAngle: '輸入角',
  openFull: '開啟完整模擬器',
  embedTitle: '四連桿機構模擬器',

  errorTitle: '發生錯誤',
  errorBody: '模擬器遇到非預期的錯誤。最後的設定保留在網址列中。',
  errorReset: '重設為預設機構',
};
