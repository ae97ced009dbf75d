/**
 * The Mechanisms page's bench:ui figures (issue 33's speed targets), on Jansen's leg with three traces and its two
 * plots (the foot link's angle and the foot's speed, whose rates the worker solves):
 *   - dragging a joint (the knee G) by pointer at a CPU slowdown: each input's response time, from the pointer event's
 *     time stamp to the end of the frame that first shows it (the commit that draws the moved linkage: the stage's
 *     data-pose), p50 and p95; the cycle (traces and the plots of positions, data-trace) follows when the pointer rests
 *     and the speed plot from the worker after it: both are timed apart from the last move, not targets;
 *   - Play at a CPU slowdown: redraws per second (frames that drew a new input) and the longest gap between them.
 * Each also reports the page thread's CPU time per input or redraw (CDP Performance.getMetrics TaskDuration), which a
 * busy machine disturbs less than the wall figures. Used by bench/ui.bench.ts (BENCH_ONLY=mech).
 */
import type { Browser, BrowserContext, Page } from 'playwright';

/** Issue 33's targets: the drag's p95 response at 4x CPU (ms, below) and Play's redraws per second at 4x (at least). */
export const MECH_TARGETS = { dragP95Ms4x: 50, playFps4x: 50 } as const;

/** Jansen's leg with the foot, the knee G and the joint E traced, and the two default plots. */
export const MECH_BENCH_QUERY = 'page=mech&tpl=jansen&mtr=3*Foot*G*E';
/** Pointer moves in a drag, one per animation frame, each 1 CSS pixel to the right. */
const DRAG_MOVES = 90;
/** The dragged joint: Jansen's knee. */
const DRAG_JOINT = 'G';

/** The in-page log: commits that drew the linkage, frame ends, pointer moves, and frames with the plots' rates shown. */
interface MechLog {
  commits: { t: number; input: string; attr: string }[];
  frameEnds: number[];
  moves: { stamp: number; handled: number }[];
  ratesReady: number[];
}

/**
 * Installed before any page script: watches the workspace's data-trace (a drawn cycle) and its stage's data-pose (a
 * drawn pose) and data-input (a drawn input), and notes each frame's end and whether the plots wait for their rates.
 */
function instrumentMech(): void {
  const log: MechLog = { commits: [], frameEnds: [], moves: [], ratesReady: [] };
  (window as unknown as { __mech: MechLog }).__mech = log;
  const observer = new MutationObserver((records) => {
    for (const r of records) {
      const el = r.target as HTMLElement;
      if (r.attributeName === 'data-trace' || r.attributeName === 'data-input' || r.attributeName === 'data-pose')
        log.commits.push({ t: performance.now(), input: el.getAttribute('data-input') ?? '', attr: r.attributeName });
    }
  });
  const watch = () => {
    const ws = document.querySelector('.mech-workspace');
    if (ws)
      observer.observe(ws, {
        attributes: true,
        subtree: true,
        attributeFilter: ['data-trace', 'data-input', 'data-pose'],
      });
    else requestAnimationFrame(watch);
  };
  requestAnimationFrame(watch);
  window.addEventListener(
    'pointermove',
    (e) => {
      if (e.buttons) log.moves.push({ stamp: e.timeStamp, handled: performance.now() });
    },
    { capture: true },
  );
  // A message posted from a rAF callback is handled after that frame has been painted.
  const channel = new MessageChannel();
  channel.port1.onmessage = () => {
    const t = performance.now();
    log.frameEnds.push(t);
    if (!document.querySelector('.mech-chart-cell .note')) log.ratesReady.push(t);
  };
  const loop = () => {
    channel.port2.postMessage(0);
    requestAnimationFrame(loop);
  };
  requestAnimationFrame(loop);
}

/** Opens the bench page at `rate`x CPU, Jansen's leg assembled and its rates solved. */
async function openMech(
  browser: Browser,
  base: string,
  rate: number,
): Promise<{ context: BrowserContext; page: Page; taskSeconds: () => Promise<number> }> {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, deviceScaleFactor: 1 });
  await context.addInitScript(instrumentMech);
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  await cdp.send('Emulation.setCPUThrottlingRate', { rate });
  await cdp.send('Performance.enable');
  await page.goto(`${base}?${MECH_BENCH_QUERY}`);
  await page.locator('.mech-workspace[data-mech-state="ok"]').waitFor({ timeout: 60_000 });
  await page.locator('.mech-chart-cell .note').waitFor({ state: 'detached', timeout: 60_000 });
  await page.waitForTimeout(800);
  const taskSeconds = async () => {
    const { metrics } = await cdp.send('Performance.getMetrics');
    return metrics.find((m) => m.name === 'TaskDuration')?.value ?? Number.NaN;
  };
  return { context, page, taskSeconds };
}

/** The q-quantile of sorted values (nearest rank). */
function quantile(sorted: readonly number[], q: number): number {
  if (sorted.length === 0) return Number.NaN;
  return sorted[Math.min(sorted.length - 1, Math.ceil(q * sorted.length) - 1)];
}

/**
 * One drag of the knee: response p50 and p95 (ms), inputs never shown, page-thread CPU ms per input, and from the last
 * move's time stamp to the end of the frame showing the new cycle (traces, plots of positions) and the speed plot (ms).
 */
export interface MechDragFigures {
  p50Ms: number;
  p95Ms: number;
  withoutRedraw: number;
  cpuMsPerInput: number;
  cycleMs: number;
  ratesMs: number;
}

/**
 * Drags Jansen's knee by pointer (page.mouse: real input events), one move per animation frame. An input is shown by
 * the first commit after its handler ran (React draws the latest state); its response time runs from the event's
 * time stamp to the end of that commit's frame.
 */
export async function measureMechDrag(browser: Browser, base: string, rate: number): Promise<MechDragFigures> {
  const { context, page, taskSeconds } = await openMech(browser, base, rate);
  try {
    const canvas = page.getByTestId('mech-canvas');
    const box = (await canvas.boundingBox())!;
    const [scale, cx, cy, panX, panY] = (await canvas.getAttribute('data-view'))!.split(' ').map(Number);
    const x = Number(await page.getByRole('textbox', { name: `x of ${DRAG_JOINT}`, exact: true }).inputValue());
    const y = Number(await page.getByRole('textbox', { name: `y of ${DRAG_JOINT}`, exact: true }).inputValue());
    const at = {
      x: box.x + box.width / 2 + (x - cx) * scale + panX,
      y: box.y + box.height / 2 - (y - cy) * scale + panY,
    };
    const frame = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r(0))));
    // A warm-up drag there and back (the JIT, the worker), then the measured one.
    await page.mouse.move(at.x, at.y);
    await page.mouse.down();
    for (let i = 1; i <= 20; i++) {
      await page.mouse.move(at.x + (i <= 10 ? i : 20 - i), at.y);
      await frame();
    }
    await page.mouse.up();
    await page.waitForTimeout(1500);
    const cpu0 = await taskSeconds();
    await page.evaluate(() => {
      const log = (window as unknown as { __mech: MechLog }).__mech;
      log.commits.length = 0;
      log.moves.length = 0;
      log.frameEnds.length = 0;
      log.ratesReady.length = 0;
    });
    await page.mouse.move(at.x, at.y);
    const trace0 = await page.locator('.mech-workspace').getAttribute('data-trace');
    await page.mouse.down();
    for (let i = 1; i <= DRAG_MOVES; i++) {
      await page.mouse.move(at.x + i, at.y);
      await frame();
    }
    // Held still until the cycle and then the speed plot show the moved linkage (a busy machine can take seconds).
    await page.waitForFunction(
      (t0) => document.querySelector('.mech-workspace')?.getAttribute('data-trace') !== t0,
      trace0,
      { timeout: 30_000 },
    );
    await page.locator('.mech-chart-cell .note').waitFor({ state: 'detached', timeout: 30_000 });
    await page.waitForTimeout(300);
    const cpu1 = await taskSeconds();
    await page.mouse.up();
    const log = await page.evaluate(() => (window as unknown as { __mech: MechLog }).__mech);
    const moves = log.moves.slice(1);
    // A build before data-pose (the drag swept the linkage at every move) shows a move by its traces.
    const drawn = log.commits.some((k) => k.attr === 'data-pose') ? 'data-pose' : 'data-trace';
    const latencies = moves.map((m) => {
      const c = log.commits.find((k) => k.t >= m.handled && k.attr === drawn);
      const end = c && log.frameEnds.find((f) => f > c.t);
      return end === undefined ? null : end - m.stamp;
    });
    const last = moves[moves.length - 1];
    const cycle = last && log.commits.find((k) => k.t >= last.handled && k.attr === 'data-trace');
    const cycleEnd = cycle && log.frameEnds.find((f) => f > cycle.t);
    const ratesEnd = cycle && log.ratesReady.find((f) => f > cycle.t);
    const sorted = (xs: (number | null)[]) => xs.filter((v): v is number => v !== null).sort((a, b) => a - b);
    const lat = sorted(latencies);
    return {
      p50Ms: quantile(lat, 0.5),
      p95Ms: quantile(lat, 0.95),
      withoutRedraw: latencies.filter((v) => v === null).length,
      cpuMsPerInput: ((cpu1 - cpu0) * 1000) / Math.max(1, moves.length),
      cycleMs: cycleEnd === undefined ? Number.NaN : cycleEnd - last.stamp,
      ratesMs: ratesEnd === undefined ? Number.NaN : ratesEnd - last.stamp,
    };
  } finally {
    await context.close();
  }
}

/** Play: redraws per second (frames with a new input drawn), the longest gap (ms), page-thread CPU ms per redraw. */
export interface MechPlayFigures {
  redrawFps: number;
  longestGapMs: number;
  cpuMsPerRedraw: number;
}

/** seconds of Play on Jansen's leg at `rate`x CPU. */
export async function measureMechPlay(
  browser: Browser,
  base: string,
  rate: number,
  seconds: number,
): Promise<MechPlayFigures> {
  const { context, page, taskSeconds } = await openMech(browser, base, rate);
  try {
    await page.getByRole('button', { name: 'Play' }).click();
    await page.waitForTimeout(500);
    const cpu0 = await taskSeconds();
    const r = await page.evaluate(async (s) => {
      const log = (window as unknown as { __mech: MechLog }).__mech;
      const start = performance.now();
      const from = log.commits.length;
      await new Promise((done) => setTimeout(done, s * 1000));
      const end = performance.now();
      return {
        commits: log.commits.slice(from),
        ends: log.frameEnds.filter((f) => f >= start && f <= end),
        start,
        end,
      };
    }, seconds);
    const cpu1 = await taskSeconds();
    await page.getByRole('button', { name: 'Pause' }).click();
    // A redraw counts once per painted frame, and only with a new input.
    const frames = new Set<number>();
    let last = '';
    const times: number[] = [];
    for (const c of r.commits) {
      if (c.attr !== 'data-input' || c.input === last) continue;
      last = c.input;
      const end = r.ends.find((f) => f > c.t);
      if (end !== undefined && !frames.has(end)) {
        frames.add(end);
        times.push(end);
      }
    }
    let gap = 0;
    for (let i = 1; i < times.length; i++) gap = Math.max(gap, times[i] - times[i - 1]);
    return {
      redrawFps: times.length / ((r.end - r.start) / 1000),
      longestGapMs: gap,
      cpuMsPerRedraw: ((cpu1 - cpu0) * 1000) / Math.max(1, times.length),
    };
  } finally {
    await context.close();
  }
}
