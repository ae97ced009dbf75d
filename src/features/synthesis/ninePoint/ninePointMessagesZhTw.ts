import type { NinePointMessages } from './ninePointMessages';

/** Traditional Chinese (Taiwan) strings of the Nine points mode (九點精確合成). */
export const ninePointMessagesZhTw: NinePointMessages = {
  intro:
    '放置恰好九個目標點：找出耦桿曲線恰好通過全部九點的每一個四連桿（Alt 問題；四連桿最多能通過九點），' +
    '方法是在處理器的各核心上追蹤多項式同倫的 1442 條路徑（Wampler、Morgan 與 Sommese，1992）。',
  needNine: (count) => `九點精確合成需要恰好 9 個目標點；目前有 ${count} 個。`,
  refusalCoincide: (i, j, x, y) => `第 ${i} 點與第 ${j} 點重合於 (${x}, ${y})：需要九個相異的點。`,
  refusalLine: '九點共線：所有解都在無窮遠處。請把一點移離該直線。',
  refusalCircle: '九點共圓：所有解都在無窮遠處。請把一點移離該圓。',
  exampleProblem3: '範例：Problem 3（Wampler、Morgan、Sommese）',
  solve: '找出所有連桿',
  cancel: '取消',
  progressLabel: '已追蹤的路徑',
  progressText: (done, total, roots, rootsTotal, real) =>
    `${total} 條路徑中已完成 ${done} 條（${rootsTotal} 個根中 ${roots} 個）· 目前實根 ${real} 個`,
  statusRunning: (workers) => `正在以 ${workers} 個工作執行緒追蹤路徑…`,
  statusDone: (finished, total, roots, rootsTotal, failed, seconds, workers) =>
    `${total} 條路徑中 ${finished} 條完成（${rootsTotal} 個根中 ${roots} 個），以 ${workers} 個工作執行緒費時 ${seconds} 秒` +
    (failed > 0 ? `；${failed} 條路徑失敗，可能缺少某個類別。` : '。'),
  statusCancelled: (tracked, total, roots, rootsTotal) =>
    `已取消：${total} 條路徑中追蹤了 ${tracked} 條（${rootsTotal} 個根中 ${roots} 個）；下列只是目前找到的類別，並非全部。`,
  statusFailed: (why) => `執行失敗：${why}`,
  statusRetracked: (n) => `有 ${n} 條路徑因兩條路徑收斂到同一解而重新仔細追蹤。`,
  classCount: (classes, linkages) => `${classes} 個實數連桿類別，共 ${linkages} 個連桿`,
  noClasses: '沒有實數連桿通過這九點。',
  classesTitle: '連桿類別',
  filtersLegend: '只顯示',
  filterGrashof: 'Grashof',
  filterCrank: '曲柄輸入',
  filterNoDefect: '無迴路或順序缺陷',
  maxSizeLabel: '最長桿長上限',
  maxSizeHelp: '空白：不限大小。類別中任一同源機構符合即可。',
  maxSizeError: (text) => `最長桿長上限：${JSON.stringify(text)} 不是正數。`,
  sortLabel: '排序',
  sortText: { found: '找到的順序', size: '由小到大', transmission: '傳動角最佳' },
  shownCount: (shown, total) => `顯示 ${total} 個類別中的 ${shown} 個`,
  noneMatch: '沒有類別符合這些條件。',
  className: (n) => `類別 ${n}`,
  longestLink: '最長桿',
  crankInput: '曲柄輸入',
  noCrank: '無曲柄',
  defectsLabel: '缺陷',
  noDefects: '無',
  defectText: {
    circuit: '迴路缺陷（各點分屬兩個迴路）',
    order: '順序缺陷（一圈內未依序通過）',
    branch: '分支缺陷（兩點之間經過死點）',
  },
  optimiserWorse: (distance) => `最佳化（路徑生成）對這九點的最大誤差為 ${distance}；此處每個類別都恰好通過全部九點。`,
};
