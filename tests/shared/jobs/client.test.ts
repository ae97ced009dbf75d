import { afterEach, describe, expect, it, vi } from 'vitest';
import { solverApi } from '../../../src/workers/api';
import { SolverClient, SolverError } from '../../../src/shared/jobs/client';
import { DEFAULT_WATCHDOG, budgetMs } from '../../../src/shared/jobs/watchdog';
import type { SolverMode, SolverModeReason, WorkerLike } from '../../../src/shared/jobs/client';
import { expose } from '../../../src/shared/jobs/expose';
import type { CallRequest, SolverApi, SolverRequest, SolverResponse } from '../../../src/shared/jobs/protocol';

const L = { r1: 6, r2: 2, r3: 5, r4: 5 };
const C = { distance: 2.5, angleRad: Math.PI / 6 };
const SOLVER = { method: 'newton' as const, tol: null };
const point = (theta2Rad: number) => ({
  linkage: L,
  branch: 'open' as const,
  theta2Rad,
  stepRad: Math.PI / 180,
  coupler: C,
  solver: SOLVER,
  ghost: true,
  newton: true,
});
const CYCLE = {
  linkage: L,
  samples: 36,
  coupler: C,
  solver: SOLVER,
  branch: 'open' as const,
  otherBranch: true,
  curves: true,
};
const LAB = { linkage: L, branch: 'open' as const, stepDeg: 1 };

/**
 * A fake Worker serving an API object through the real expose(): requests wait in `received` until the
 * test delivers them (or at once when auto), answers cross a structured clone with their transfer list,
 * as they would between threads. A dead worker (close() in it) takes requests and never answers.
 */
class FakeWorker implements WorkerLike {
  received: SolverRequest[] = [];
  delivered = 0;
  terminated = false;
  dead = false;
  private toClient: Record<string, ((e: Event) => void)[]> = { message: [], error: [], messageerror: [] };
  private toApi: ((e: MessageEvent) => void) | null = null;
  constructor(
    api: SolverApi = solverApi,
    private auto = false,
  ) {
    expose(api, {
      postMessage: (message: SolverResponse, transfer: Transferable[]) => {
        if (this.terminated) return;
        const data = structuredClone(message, { transfer });
        for (const l of this.toClient.message) l({ data } as MessageEvent);
      },
      addEventListener: (_type, l) => {
        this.toApi = l;
      },
    });
  }
  postMessage(message: SolverRequest): void {
    if (this.terminated || this.dead) return;
    this.received.push(message);
    if (this.auto) this.deliverAll();
  }
  addEventListener(type: string, listener: (e: Event) => void): void {
    this.toClient[type].push(listener);
  }
  terminate(): void {
    this.terminated = true;
  }
  /** Hands the next waiting request to the API and lets it answer. */
  async deliver(): Promise<void> {
    this.toApi?.({ data: this.received[this.delivered++] } as MessageEvent);
    await flush();
  }
  deliverAll(): void {
    while (this.delivered < this.received.length)
      this.toApi?.({ data: this.received[this.delivered++] } as MessageEvent);
  }
  error(message: string): void {
    for (const l of this.toClient.error) l({ message, preventDefault: () => undefined } as unknown as Event);
  }
  calls(): CallRequest[] {
    return this.received.filter((r): r is CallRequest => r.type !== 'cancel');
  }
}

/** Lets promise callbacks (and expose's awaited answers) run. */
async function flush(): Promise<void> {
  for (let i = 0; i < 5; i++) await Promise.resolve();
}

afterEach(() => {
  vi.useRealTimers();
});

describe('SolverClient latest wins', () => {
  it('keeps one call in flight and one queued per channel: no backlog while a slider is dragged', async () => {
    const w = new FakeWorker();
    const client = new SolverClient({ createWorker: () => w });
    const results: (number | null)[] = [];
    const all = [0.1, 0.2, 0.3, 0.4, 0.5].map((t) =>
      client.point(point(t)).then((r) => results.push(r ? r.theta2Rad : null)),
    );
    expect(w.received).toHaveLength(1);
    await w.deliver();
    // Only the newest queued call is sent next; the ones queued between were never sent.
    expect(w.calls().map((r) => r.type === 'point' && r.params.theta2Rad)).toEqual([0.1, 0.5]);
    await w.deliver();
    await Promise.all(all);
    // The answer that was in flight still arrives (it is newer than anything shown), in order, then the newest.
    expect(results.filter((r) => r !== null)).toEqual([0.1, 0.5]);
    expect(results).toHaveLength(5);
    client.dispose();
  });

  it('drops a table call in flight when a newer one comes (an export downloads once)', async () => {
    const w = new FakeWorker();
    const client = new SolverClient({ createWorker: () => w });
    const table = (samples: number) => ({ linkage: L, samples, branch: 'open' as const, solver: SOLVER });
    const first = client.table(table(36), 'export');
    const second = client.table(table(72), 'export');
    await w.deliver();
    await w.deliver();
    expect(await first).toBeNull();
    expect((await second)?.theta2Deg).toHaveLength(73);
    client.dispose();
  });

  it('always ends with the last value solved', async () => {
    const w = new FakeWorker();
    const client = new SolverClient({ createWorker: () => w });
    const first = client.point(point(1));
    await w.deliver();
    expect((await first)?.theta2Rad).toBe(1);
    const last = client.point(point(2));
    await w.deliver();
    expect((await last)?.theta2Rad).toBe(2);
    client.dispose();
  });

  it('keeps the cycle, point and table channels independent', async () => {
    const w = new FakeWorker();
    const client = new SolverClient({ createWorker: () => w });
    const c = client.cycle(CYCLE);
    const p = client.point(point(1));
    const t = client.table({ linkage: L, samples: 36, branch: 'crossed', solver: SOLVER });
    const e = client.table({ linkage: L, samples: 72, branch: 'open', solver: SOLVER }, 'export');
    expect(w.received.map((r) => r.type)).toEqual(['cycle', 'point', 'table', 'table']);
    for (let i = 0; i < 4; i++) await w.deliver();
    expect((await c)?.theta2Deg.length).toBe(37);
    expect((await p)?.theta2Rad).toBe(1);
    expect((await t)?.theta3Rad.length).toBe(37);
    expect((await e)?.theta3Rad.length).toBe(73);
    client.dispose();
  });

  it('gets the answer’s arrays intact after they crossed as transferred buffers', async () => {
    const w = new FakeWorker(solverApi, true);
    const client = new SolverClient({ createWorker: () => w });
    const r = await client.cycle(CYCLE);
    expect(r?.open.theta3).toBeInstanceOf(Float64Array);
    expect(r?.open.okCount).toBe(37);
    // Hard case 1 at theta2 = 90 deg, grid index 9 of 36 (60-digit reference).
    expect((r!.open.theta3[9] * 180) / Math.PI).toBeCloseTo(32.3335306935, 7);
    client.dispose();
  });
});

describe('SolverClient errors', () => {
  it('rejects with the API’s message, labelled with the call’s type, and the channel keeps working', async () => {
    const w = new FakeWorker(solverApi, true);
    const client = new SolverClient({ createWorker: () => w });
    const bad = client.cycle({ ...CYCLE, linkage: { r1: 6, r2: -1, r3: 5, r4: 5 } });
    await expect(bad).rejects.toThrow(/r2 must be a positive finite length, got -1/);
    const err = await bad.catch((e: unknown) => e);
    expect(err).toBeInstanceOf(SolverError);
    expect((err as SolverError).response.requestType).toBe('cycle');
    expect((await client.cycle(CYCLE))?.classification.type).toBe('crank-rocker');
    client.dispose();
  });
});

describe('SolverClient lab', () => {
  /** A lab that reports a stage per macrotask until cancelled or done after `stages`. */
  const slowLab = (stages: number): SolverApi => ({
    ...solverApi,
    async lab(params, task) {
      for (let i = 0; i < stages; i++) {
        task.progress(i / stages, `stage ${i}`);
        await new Promise((r) => setTimeout(r, 0));
        if (task.cancelled()) return null;
      }
      return { linkage: params.linkage, stepDeg: params.stepDeg } as never;
    },
  });

  it('passes progress on and resolves with the result', async () => {
    const w = new FakeWorker(slowLab(3), true);
    const client = new SolverClient({ createWorker: () => w });
    const progress: string[] = [];
    const run = client.lab(LAB, (f, s) => progress.push(`${f.toFixed(2)} ${s}`));
    expect(await run.result).toMatchObject({ stepDeg: 1 });
    expect(progress).toEqual(['0.00 stage 0', '0.33 stage 1', '0.67 stage 2']);
    client.dispose();
  });

  it('cancel() resolves the run to null and tells the worker to stop', async () => {
    const w = new FakeWorker(slowLab(1000), true);
    const client = new SolverClient({ createWorker: () => w });
    const progress: number[] = [];
    const run = client.lab(LAB, (f) => progress.push(f));
    await new Promise((r) => setTimeout(r, 5));
    run.cancel();
    expect(await run.result).toBeNull();
    expect(w.received.map((r) => r.type)).toEqual(['lab', 'cancel']);
    // The worker answers null at its next stage; the next study then starts.
    const next = client.lab({ ...LAB, stepDeg: 2 }, () => undefined);
    next.cancel();
    await new Promise((r) => setTimeout(r, 20));
    expect(progress.length).toBeLessThan(1000);
    expect(w.calls().map((r) => r.type === 'lab' && r.params.stepDeg)).toEqual([1]);
    client.dispose();
  });

  it('a newer study supersedes a running one: the old resolves to null, is cancelled, and the new one runs', async () => {
    const w = new FakeWorker(slowLab(3), true);
    const client = new SolverClient({ createWorker: () => w });
    const old = client.lab(LAB, () => undefined);
    const fresh = client.lab({ ...LAB, stepDeg: 0.5 }, () => undefined);
    expect(await old.result).toBeNull();
    expect(await fresh.result).toMatchObject({ stepDeg: 0.5 });
    expect(w.received.map((r) => r.type)).toEqual(['lab', 'cancel', 'lab']);
    client.dispose();
  });
});

describe('SolverClient watchdog', () => {
  const WATCHDOG = { startMs: 1000, baseMs: 100, perPointMs: 0.01, labStageMs: 500 };

  /** A client over a list of fake workers (made in turn), recording its modes. */
  function setup(workers: FakeWorker[], fallback = new FakeWorker(solverApi, true)) {
    const modes: [SolverMode, SolverModeReason | null][] = [];
    let made = 0;
    const client = new SolverClient({
      createWorker: () => workers[made++],
      createFallback: () => fallback,
      watchdog: WATCHDOG,
      onModeChange: (m, r) => modes.push([m, r]),
    });
    return { client, modes, made: () => made, fallback };
  }

  it('gives each call a budget that grows with its work', () => {
    const w = DEFAULT_WATCHDOG;
    expect(budgetMs('point', point(1), w)).toBeGreaterThanOrEqual(w.baseMs);
    expect(budgetMs('cycle', { ...CYCLE, samples: 3600 }, w)).toBeGreaterThan(budgetMs('cycle', CYCLE, w));
    expect(budgetMs('table', { linkage: L, samples: 36000, branch: 'open', solver: SOLVER }, w)).toBeGreaterThan(
      budgetMs('table', { linkage: L, samples: 360, branch: 'open', solver: SOLVER }, w),
    );
    expect(budgetMs('lab', LAB, w)).toBe(w.labStageMs);
  });

  it('restarts a worker that stops answering, once, then solves on the main thread', async () => {
    vi.useFakeTimers();
    const first = new FakeWorker(solverApi, true);
    const second = new FakeWorker(solverApi, true);
    const { client, modes, made, fallback } = setup([first, second]);
    expect((await client.point(point(0.1)))?.theta2Rad).toBe(0.1);
    expect(client.mode).toBe('worker');
    first.dead = true; // close() inside the worker: requests vanish, nothing is said.
    const p = client.point(point(0.2));
    const budget = budgetMs('point', point(0.2), { ...DEFAULT_WATCHDOG, ...WATCHDOG });
    await vi.advanceTimersByTimeAsync(budget - 1);
    expect(made()).toBe(1);
    await vi.advanceTimersByTimeAsync(2);
    expect(made()).toBe(2);
    expect(first.terminated).toBe(true);
    expect((await p)?.theta2Rad).toBe(0.2);
    expect([client.mode, client.reason]).toEqual(['restarted', 'stopped']);
    second.dead = true;
    const c = client.cycle(CYCLE);
    await vi.advanceTimersByTimeAsync(budgetMs('cycle', CYCLE, { ...DEFAULT_WATCHDOG, ...WATCHDOG }) + 1);
    expect((await c)?.theta2Deg.length).toBe(37);
    expect(fallback.calls().map((r) => r.type)).toEqual(['cycle']);
    expect(modes).toEqual([
      ['worker', null],
      ['restarted', 'stopped'],
      ['main-thread', 'stopped'],
    ]);
    client.dispose();
  });

  it('restarts at once on a worker error, and resends only the newest call of a channel', async () => {
    const first = new FakeWorker();
    const second = new FakeWorker(solverApi, true);
    const { client, modes } = setup([first, second]);
    const a = client.point(point(0.1));
    const b = client.point(point(0.2));
    first.error('boom');
    // At once, not after the watchdog's budget.
    expect(first.terminated).toBe(true);
    expect(second.calls()).toHaveLength(1);
    expect(await a).toBeNull();
    expect((await b)?.theta2Rad).toBe(0.2);
    expect(second.calls().map((r) => r.type === 'point' && r.params.theta2Rad)).toEqual([0.2]);
    expect(modes).toEqual([['restarted', 'unavailable']]);
    client.dispose();
  });

  it('lets a long study run as long as its progress keeps coming', async () => {
    vi.useFakeTimers();
    let stage = 0;
    const lab: SolverApi = {
      ...solverApi,
      async lab(params, task) {
        // Ten stages of 400 ms each: 4 s in all, eight times the 500 ms stage budget.
        for (stage = 0; stage < 10; stage++) {
          task.progress(stage / 10, 'stage');
          await new Promise((r) => setTimeout(r, 400));
        }
        return { stepDeg: params.stepDeg } as never;
      },
    };
    const w = new FakeWorker(lab, true);
    const { client, made } = setup([w]);
    const run = client.lab(LAB, () => undefined);
    await vi.advanceTimersByTimeAsync(4500);
    expect(await run.result).toEqual({ stepDeg: 1 });
    expect(made()).toBe(1);
    expect(client.mode).toBe('worker');
    client.dispose();
  });

  it('does not blame the worker when its own timer fires late (this thread was busy)', async () => {
    vi.useFakeTimers();
    const w = new FakeWorker();
    const { client, made } = setup([w]);
    const p = client.point(point(0.3));
    // The clock jumps past the deadline without the timer firing: a long task on this thread.
    vi.setSystemTime(Date.now() + 5000);
    await vi.advanceTimersByTimeAsync(WATCHDOG.startMs + WATCHDOG.baseMs + 1);
    expect(made()).toBe(1);
    await w.deliver();
    expect((await p)?.theta2Rad).toBe(0.3);
    client.dispose();
  });

  it('solves on the main thread, with the same API, when no worker can start', async () => {
    const modes: [SolverMode, SolverModeReason | null][] = [];
    const client = new SolverClient({
      createWorker: () => {
        throw new Error('SecurityError: opaque origin');
      },
      onModeChange: (m, r) => modes.push([m, r]),
    });
    expect(client.mode).toBe('main-thread');
    const r = await client.cycle({ ...CYCLE, samples: 360 });
    expect(r?.theta2Deg.length).toBe(361);
    await expect(client.point({ ...point(1), linkage: { ...L, r3: 0 } })).rejects.toThrow(/r3 .*got 0/);
    expect(modes).toEqual([['main-thread', 'unavailable']]);
    client.dispose();
  });

  it('resolves everything pending to null on dispose', async () => {
    const w = new FakeWorker();
    const client = new SolverClient({ createWorker: () => w });
    const a = client.cycle(CYCLE);
    const b = client.cycle(CYCLE);
    client.dispose();
    expect([await a, await b]).toEqual([null, null]);
    expect(w.terminated).toBe(true);
    expect(await client.point(point(1))).toBeNull();
  });
});
