/**
 * The Mechanisms page's bench:ui figures (issue 33's speed targets), on Jansen's leg with three traces and its two
 * plots (the foot link's angle and the foot's speed, whose rates the worker solves):
 *   - dragging a joint (the knee G) by pointer at a CPU slowdown: each input's response time, from the pointer event's
 *     time stamp to the end of the frame that first shows it (the commit that draws the moved linkage: the stage's
 *     data-pose), p50 and p95; the cycle (traces and the plots of positions, data-trace) follows when the pointer rests
 *     and the speed plot from the worker after it: both are timed apart from the last move, not targets;
 *   - Play at a CPU slowdown: redraws per second (frames that drew a new input) and the longest gap between them.
 * Each also reports the page thread's CPU time per input or redraw (CDP Performance.getMetrics TaskDuration), which a
 * busy machine disturbs less than the wall figures. Where the page's live stage draws (a worker on an OffscreenCanvas:
 * features/mechanism/stage), a move is shown by the stage's frame (the app's 'fourbar:mech-stage-frame' mark: drawn,
 * then on screen at the worker's next animation frame) and Play's redraws are the stage's frames. CDP's CPU throttling
 * slows the page's main thread, not its workers, so measureMechWorkerCost also traces the stage worker's own CPU time
 * per frame at 1x (what a core 4x slower pays is about 4 times that). Used by bench/ui.bench.ts (BENCH_ONLY=mech).
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

/** A frame the live stage's worker drew: its run's mode, the input, when (page ms) drawn and shown, its draw's ms. */
interface StageFrame {
  mode: 'play' | 'show';
  input: number;
  t: number;
  shown: number;
  drawMs: number;
}

/**
 * The in-page log: commits that drew the linkage, frame ends, pointer moves, frames with the plots' rates shown, and
 * the live stage's frames.
 */
interface MechLog {
  commits: { t: number; input: string; attr: string }[];
  frameEnds: number[];
  moves: { stamp: number; handled: number }[];
  ratesReady: number[];
  stage: StageFrame[];
}

/**
 * Installed before any page script: watches the workspace's data-trace (a drawn cycle) and its stage's data-pose (a
 * drawn pose) and data-input (a drawn input), and notes each frame's end and whether the plots wait for their rates.
 */
function instrumentMech(): void {
  const log: MechLog = { commits: [], frameEnds: [], moves: [], ratesReady: [], stage: [] };
  const w = window as unknown as { __mech: MechLog; __FOURBAR_BENCH__: boolean };
  w.__mech = log;
  // The app's bench marks (the live stage's frames) are made only under this flag.
  w.__FOURBAR_BENCH__ = true;
  new PerformanceObserver((list) => {
    for (const e of list.getEntries())
      if (e.name === 'fourbar:mech-stage-frame') log.stage.push((e as PerformanceMark).detail as StageFrame);
  }).observe({ type: 'mark', buffered: false });
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

/** Where the canvas draws joint id as drawn (page pixels): its coordinates from the table, the view from data-view. */
async function jointOnScreen(page: Page, id: string): Promise<{ x: number; y: number }> {
  const canvas = page.getByTestId('mech-canvas');
  const box = (await canvas.boundingBox())!;
  const [scale, cx, cy, panX, panY] = (await canvas.getAttribute('data-view'))!.split(' ').map(Number);
  const x = Number(await page.getByRole('textbox', { name: `x of ${id}`, exact: true }).inputValue());
  const y = Number(await page.getByRole('textbox', { name: `y of ${id}`, exact: true }).inputValue());
  return { x: box.x + box.width / 2 + (x - cx) * scale + panX, y: box.y + box.height / 2 - (y - cy) * scale + panY };
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
  /** Frames the live stage drew for the drag (0: the page drew it) and their mean draw time in the worker (ms). */
  stageFrames: number;
  stageDrawMs: number;
}

/** The mean of values (NaN for none). */
const mean = (xs: readonly number[]) => (xs.length ? xs.reduce((a, b) => a + b, 0) / xs.length : Number.NaN);

/**
 * Drags Jansen's knee by pointer (page.mouse: real input events), one move per animation frame. An input is shown by
 * the first commit after its handler ran (React draws the latest state); its response time runs from the event's
 * time stamp to the end of that commit's frame.
 */
export async function measureMechDrag(browser: Browser, base: string, rate: number): Promise<MechDragFigures> {
  const { context, page, taskSeconds } = await openMech(browser, base, rate);
  try {
    const at = await jointOnScreen(page, DRAG_JOINT);
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
      log.stage.length = 0;
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
    // Drawn by the live stage: the first of its frames drawn after the move's handler ran shows it.
    const shows = log.stage.filter((f) => f.mode === 'show');
    const latencies = moves.map((m) => {
      if (shows.length > 0) {
        const f = shows.find((k) => k.t >= m.handled);
        return f ? f.shown - m.stamp : null;
      }
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
      stageFrames: shows.length,
      stageDrawMs: mean(shows.map((f) => f.drawMs)),
    };
  } finally {
    await context.close();
  }
}

/**
 * Play: redraws per second (frames with a new input drawn, by the page or by the live stage's worker), the longest gap
 * (ms), page-thread CPU ms per redraw, the page's own frames per second, and the stage's frames and mean draw ms.
 */
export interface MechPlayFigures {
  redrawFps: number;
  longestGapMs: number;
  cpuMsPerRedraw: number;
  pageFps: number;
  stageFrames: number;
  stageDrawMs: number;
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
      const fromStage = log.stage.length;
      await new Promise((done) => setTimeout(done, s * 1000));
      const end = performance.now();
      return {
        commits: log.commits.slice(from),
        stage: log.stage.slice(fromStage).filter((f) => f.mode === 'play' && f.t >= start && f.t <= end),
        ends: log.frameEnds.filter((f) => f >= start && f <= end),
        start,
        end,
      };
    }, seconds);
    const cpu1 = await taskSeconds();
    await page.getByRole('button', { name: 'Pause' }).click();
    // A redraw counts once per painted frame, and only with a new input: the stage's frames where it drew Play.
    const frames = new Set<number>();
    let last = '';
    const times: number[] = [];
    for (const f of r.stage) {
      if (String(f.input) === last) continue;
      last = String(f.input);
      times.push(f.shown);
    }
    for (const c of r.stage.length > 0 ? [] : r.commits) {
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
    const spanS = (r.end - r.start) / 1000;
    return {
      redrawFps: times.length / spanS,
      longestGapMs: gap,
      cpuMsPerRedraw: ((cpu1 - cpu0) * 1000) / Math.max(1, times.length),
      pageFps: r.ends.length / spanS,
      stageFrames: r.stage.length,
      stageDrawMs: mean(r.stage.map((f) => f.drawMs)),
    };
  } finally {
    await context.close();
  }
}

/**
 * The live stage worker's own CPU time per frame at 1x (ms; a trace's thread time of every task on the worker's thread,
 * so the canvas's rasterising and hand-over count, not only the drawing's script), for Play and for a drag's moves,
 * with the frames it drew. NaN where no stage drew (the page drew itself).
 */
export interface MechWorkerCost {
  playMsPerFrame: number;
  playFrames: number;
  dragMsPerFrame: number;
  dragFrames: number;
}

interface TraceEvent {
  ph: string;
  name: string;
  pid: number;
  tid: number;
  dur?: number;
  tdur?: number;
  args?: { name?: string };
}

/**
 * The CPU ms of the stage worker's thread in a trace: the dedicated worker thread that ran animation frames (the solver
 * worker has none), summing its top-level tasks' thread time.
 */
function stageWorkerMs(events: TraceEvent[]): number {
  const threadOf = (e: TraceEvent) => `${e.pid}:${e.tid}`;
  const workers = new Set(
    events.filter((e) => e.ph === 'M' && e.args?.name === 'DedicatedWorker thread').map(threadOf),
  );
  const animating = new Set(events.filter((e) => e.name === 'FireAnimationFrame').map(threadOf));
  let ms = 0;
  let found = false;
  for (const e of events) {
    const k = threadOf(e);
    if (e.ph !== 'X' || e.name !== 'RunTask' || !workers.has(k) || !animating.has(k)) continue;
    found = true;
    ms += (e.tdur ?? e.dur ?? 0) / 1000;
  }
  return found ? ms : Number.NaN;
}

/** Traces the stage worker during run(); its CPU ms and the frames of `mode` it drew meanwhile. */
async function tracedStage(
  browser: Browser,
  page: Page,
  mode: StageFrame['mode'],
  run: () => Promise<void>,
): Promise<{ ms: number; frames: number }> {
  const from = await page.evaluate(() => (window as unknown as { __mech: MechLog }).__mech.stage.length);
  await browser.startTracing(page, {
    categories: ['toplevel', 'devtools.timeline', 'disabled-by-default-devtools.timeline', '__metadata'],
  });
  await run();
  const buffer = await browser.stopTracing();
  const parsed = JSON.parse(buffer.toString()) as { traceEvents?: TraceEvent[] } | TraceEvent[];
  const events = Array.isArray(parsed) ? parsed : (parsed.traceEvents ?? []);
  const frames = await page.evaluate(
    ([start, m]) =>
      (window as unknown as { __mech: MechLog }).__mech.stage.slice(start as number).filter((f) => f.mode === m).length,
    [from, mode] as const,
  );
  return { ms: stageWorkerMs(events), frames };
}

/** The stage worker's CPU ms per frame at 1x: `seconds` of Play, then a drag of the knee (40 moves). */
export async function measureMechWorkerCost(browser: Browser, base: string, seconds: number): Promise<MechWorkerCost> {
  const { context, page } = await openMech(browser, base, 1);
  try {
    await page.getByRole('button', { name: 'Play' }).click();
    await page.waitForTimeout(500);
    const play = await tracedStage(browser, page, 'play', () => page.waitForTimeout(seconds * 1000));
    await page.getByRole('button', { name: 'Pause' }).click();
    await page.waitForTimeout(500);
    const at = await jointOnScreen(page, DRAG_JOINT);
    const frame = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r(0))));
    await page.mouse.move(at.x, at.y);
    await page.mouse.down();
    const drag = await tracedStage(browser, page, 'show', async () => {
      for (let i = 1; i <= 40; i++) {
        await page.mouse.move(at.x + i, at.y);
        await frame();
      }
    });
    await page.mouse.up();
    return {
      playMsPerFrame: play.ms / Math.max(1, play.frames),
      playFrames: play.frames,
      dragMsPerFrame: drag.ms / Math.max(1, drag.frames),
      dragFrames: drag.frames,
    };
  } finally {
    await context.close();
  }
}
