import { afterEach, describe, expect, it, vi } from 'vitest';
import { JobError } from '../../src/shared/jobs/jobClient';
import type { JobClientMode, JobClientModeReason, WorkerLike } from '../../src/shared/jobs/jobClient';
import type { JobHandlers } from '../../src/shared/jobs/jobTable';
import { SOLVE_BUDGET, simulatorJobs } from '../../src/features/simulator/jobs';
import { LAB_STAGE_MS, labJobs } from '../../src/features/lab/jobs';
import { readPathStage } from '../../src/features/synthesis/jobs';
import type { LabJobs } from '../../src/features/lab/jobs';
import { createSolverClient, solverJobs } from '../../src/workers/solverClient';
import { labHandlers } from '../../src/features/lab/labHandlers';
import { solverHandlers } from '../../src/workers/solverHandlers';
import { FakeWorker } from '../shared/jobs/fakeWorker';

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
const table = (samples: number, branch: 'open' | 'crossed' = 'open') => ({
  linkage: L,
  samples,
  branch,
  solver: SOLVER,
});
const LAB = { linkage: L, branch: 'open' as const, stepDeg: 1 };

/** The solver handlers with a lab that reports a stage per macrotask until cancelled, or done after `stages`. */
function slowLab(stages: number): typeof solverHandlers {
  const lab: JobHandlers<LabJobs>['lab'] = async (params, { signal, progress }) => {
    for (let i = 0; i < stages; i++) {
      progress(i / stages, `stage ${i}`);
      await new Promise((r) => setTimeout(r, 0));
      if (signal.aborted) return null;
    }
    return { linkage: params.linkage, stepDeg: params.stepDeg } as never;
  };
  return { ...solverHandlers, lab };
}

/** Every typed array under value (plain objects and arrays), found independently of transferablesOf. */
function typedArrays(value: unknown): ArrayBufferView[] {
  if (ArrayBuffer.isView(value)) return [value];
  if (value && typeof value === 'object') return Object.values(value).flatMap(typedArrays);
  return [];
}

afterEach(() => {
  vi.useRealTimers();
});

describe('solver jobs', () => {
  it('are the simulator’s, the lab’s, synthesis’s (path and nine points) and the mechanism page’s tables, each name once', () => {
    expect(Object.keys(solverJobs).sort()).toEqual([
      'cycle',
      'lab',
      'mechSweep',
      'ninePointPart',
      'pathMerge',
      'pathPart',
      'point',
      'table',
    ]);
    expect(Object.keys(solverHandlers).sort()).toEqual(Object.keys(solverJobs).sort());
  });

  it('run a path synthesis in parts and merge them, with progress carrying the best Σd² and candidates', async () => {
    // Six points of a known coupler curve (the report's linkage, θ2 every 60°): an exact fit exists.
    const targets = [0, 1, 2, 3, 4, 5].map((k) => {
      const t2 = (k * Math.PI) / 3;
      const ax = 2 * Math.cos(t2);
      const ay = 2 * Math.sin(t2);
      const dx = 6 - ax;
      const dy = -ay;
      const s = Math.hypot(dx, dy);
      const a = s / 2;
      const h = Math.sqrt(25 - a * a);
      const bx = ax + (a * dx - h * dy) / s;
      const by = ay + (a * dy + h * dx) / s;
      const t3 = Math.atan2(by - ay, bx - ax);
      return { x: ax + 2.5 * Math.cos(t3 + Math.PI / 6), y: ay + 2.5 * Math.sin(t3 + Math.PI / 6) };
    });
    const task = { targets, timing: { kind: 'free' as const } };
    const stages: string[] = [];
    const context = {
      signal: new AbortController().signal,
      progress: (_f: number, stage: string) => stages.push(stage),
    };
    const parts = await Promise.all(
      [0, 1].map((part) =>
        solverHandlers.pathPart({ task, seed: 1, part, parts: 2, rounds: 8, budgetMs: 30_000 }, context),
      ),
    );
    const merged = await solverHandlers.pathMerge({ task, parts: parts.map((p) => p.candidates) }, context);
    expect(merged.length).toBeGreaterThan(0);
    expect(merged[0].error).toBeLessThan(1e-20);
    expect(stages.length).toBeGreaterThan(0);
    const reported = stages.map(readPathStage);
    expect(reported.every((r) => r.best >= 0 && r.candidates.length > 0)).toBe(true);
    // What a part reports merges on its own (a stopped run's answers, issue 34 item 4).
    const last = reported[reported.length - 1];
    expect((await solverHandlers.pathMerge({ task, parts: [last.candidates] }, context)).length).toBeGreaterThan(0);
  });

  it('give each call a watchdog budget that grows with its work', () => {
    const budget = (spec: { budgetMs?(p: never): number }, p: unknown) => spec.budgetMs!(p as never);
    expect(budget(simulatorJobs.point, point(1))).toBeGreaterThanOrEqual(SOLVE_BUDGET.baseMs);
    expect(budget(simulatorJobs.cycle, { ...CYCLE, samples: 3600 })).toBeGreaterThan(
      budget(simulatorJobs.cycle, CYCLE),
    );
    expect(budget(simulatorJobs.table, table(36000))).toBeGreaterThan(budget(simulatorJobs.table, table(360)));
    expect(budget(labJobs.lab, LAB)).toBe(LAB_STAGE_MS);
  });
});

describe('the solver client, latest wins', () => {
  it('delivers the pose in flight and then only the newest: no backlog while a slider is dragged', async () => {
    const w = new FakeWorker(solverHandlers);
    const client = createSolverClient({ createWorker: () => w });
    const results: (number | null)[] = [];
    const all = [0.1, 0.2, 0.3, 0.4, 0.5].map((t) =>
      client.run('point', point(t)).result.then((r) => results.push(r ? r.theta2Rad : null)),
    );
    await w.deliver();
    expect(w.runs().map((r) => (r.params as { theta2Rad: number }).theta2Rad)).toEqual([0.1, 0.5]);
    await w.deliver();
    await Promise.all(all);
    expect(results.filter((r) => r !== null)).toEqual([0.1, 0.5]);
    client.dispose();
  });

  it('delivers the cycle in flight too, then the newest: a drag’s plots follow while the worker catches up', async () => {
    const w = new FakeWorker(solverHandlers);
    const client = createSolverClient({ createWorker: () => w });
    const first = client.run('cycle', CYCLE).result;
    const skipped = client.run('cycle', { ...CYCLE, samples: 72 }).result;
    const last = client.run('cycle', { ...CYCLE, samples: 90 }).result;
    await w.deliver();
    await w.deliver();
    expect((await first)?.samples).toBe(36);
    expect(await skipped).toBeNull();
    expect((await last)?.samples).toBe(90);
    client.dispose();
  });

  it('drops a table in flight when a newer one comes (an export downloads once)', async () => {
    const w = new FakeWorker(solverHandlers, true);
    const client = createSolverClient({ createWorker: () => w });
    const first = client.run('table', table(36), { channel: 'export' });
    const second = client.run('table', table(72), { channel: 'export' });
    expect(await first.result).toBeNull();
    expect((await second.result)?.theta2Deg).toHaveLength(73);
    client.dispose();
  });

  it('keeps the cycle, point and table channels independent', async () => {
    const w = new FakeWorker(solverHandlers);
    const client = createSolverClient({ createWorker: () => w });
    const c = client.run('cycle', CYCLE).result;
    const p = client.run('point', point(1)).result;
    const t = client.run('table', table(36, 'crossed')).result;
    const e = client.run('table', table(72), { channel: 'export' }).result;
    expect(w.runs().map((r) => r.job)).toEqual(['cycle', 'point', 'table', 'table']);
    w.deliverAll();
    expect((await c)?.theta2Deg.length).toBe(37);
    expect((await p)?.theta2Rad).toBe(1);
    expect((await t)?.theta3Rad.length).toBe(37);
    expect((await e)?.theta3Rad.length).toBe(73);
    client.dispose();
  });

  it('gets the cycle’s arrays intact after they crossed as transferred buffers', async () => {
    const w = new FakeWorker(solverHandlers, true);
    const client = createSolverClient({ createWorker: () => w });
    const r = await client.run('cycle', CYCLE).result;
    expect(r?.open.theta3).toBeInstanceOf(Float64Array);
    expect(r?.open.okCount).toBe(37);
    // 2 branches x 7 arrays, 2 curves x 2 and the grid: every one's buffer moved (some share one), none twice.
    const arrays = typedArrays(r);
    expect(arrays).toHaveLength(2 * 7 + 2 * 2 + 1);
    const transfer = w.answerTransfers[0];
    // Every buffer under the answer's arrays was moved (a clone keeps which ones share), each once, and the
    // sender holds none of them any more.
    expect(new Set(transfer).size).toBe(transfer.length);
    expect(transfer).toHaveLength(new Set(arrays.map((a) => a.buffer)).size);
    expect(transfer.every((b) => (b as ArrayBuffer).byteLength === 0)).toBe(true);
    // Hard case 1 at theta2 = 90 deg, grid index 9 of 36 (60-digit reference).
    expect((r!.open.theta3[9] * 180) / Math.PI).toBeCloseTo(32.3335306935, 7);
    client.dispose();
  });

  it('rejects with the solver’s message, labelled with the job, and the channel keeps working', async () => {
    const w = new FakeWorker(solverHandlers, true);
    const client = createSolverClient({ createWorker: () => w });
    const err = await client
      .run('cycle', { ...CYCLE, linkage: { r1: 6, r2: -1, r3: 5, r4: 5 } })
      .result.catch((e: unknown) => e);
    expect(err).toBeInstanceOf(JobError);
    expect((err as JobError).message).toMatch(/r2 must be a positive finite length, got -1/);
    expect((err as JobError).response.job).toBe('cycle');
    expect((await client.run('cycle', CYCLE).result)?.classification.type).toBe('crank-rocker');
    client.dispose();
  });
});

describe('the solver client, lab', () => {
  it('passes progress on and resolves with the result', async () => {
    const w = new FakeWorker(slowLab(3), true);
    const client = createSolverClient({ createWorker: () => w });
    const progress: string[] = [];
    const run = client.run('lab', LAB, { onProgress: (f, s) => progress.push(`${f.toFixed(2)} ${s}`) });
    expect(await run.result).toMatchObject({ stepDeg: 1 });
    expect(progress).toEqual(['0.00 stage 0', '0.33 stage 1', '0.67 stage 2']);
    client.dispose();
  });

  it('cancel() resolves the run to null and tells the worker to stop; a newer study supersedes a running one', async () => {
    const w = new FakeWorker(slowLab(1000), true);
    const client = createSolverClient({ createWorker: () => w });
    const progress: number[] = [];
    const run = client.run('lab', LAB, { onProgress: (f) => progress.push(f) });
    await new Promise((r) => setTimeout(r, 5));
    run.cancel();
    expect(await run.result).toBeNull();
    expect(w.received.map((r) => r.type)).toEqual(['run', 'cancel']);
    await new Promise((r) => setTimeout(r, 20));
    expect(progress.length).toBeLessThan(1000);
    const old = client.run('lab', LAB);
    const fresh = client.run('lab', { ...LAB, stepDeg: 0.5 });
    expect(await old.result).toBeNull();
    fresh.cancel();
    client.dispose();
  });
});

describe('labHandlers', () => {
  it('stops the real study when its signal is aborted: it answers null', async () => {
    const ac = new AbortController();
    const stages: string[] = [];
    const result = labHandlers.lab(LAB, {
      signal: ac.signal,
      progress: (_f, stage) => {
        stages.push(stage);
        ac.abort();
      },
    });
    expect(await result).toBeNull();
    expect(stages.length).toBeGreaterThan(0);
  });
});

describe('the solver client, watchdog', () => {
  /** A client over fake workers made in turn, the main-thread fallback faked too, recording its modes. */
  function setup(workers: WorkerLike[], fallback = new FakeWorker(solverHandlers, true)) {
    const modes: [JobClientMode, JobClientModeReason | null][] = [];
    let made = 0;
    const client = createSolverClient({
      createWorker: () => workers[made++],
      createFallback: () => fallback,
      onModeChange: (m, r) => modes.push([m, r]),
    });
    return { client, modes, made: () => made, fallback };
  }

  it('restarts a worker that stops answering, once, then solves on the main thread', async () => {
    vi.useFakeTimers();
    const first = new FakeWorker(solverHandlers, true);
    const second = new FakeWorker(solverHandlers, true);
    const { client, modes, made, fallback } = setup([first, second]);
    expect((await client.run('point', point(0.1)).result)?.theta2Rad).toBe(0.1);
    first.dead = true; // close() inside the worker: requests vanish, nothing is said.
    const p = client.run('point', point(0.2)).result;
    const budget = simulatorJobs.point.budgetMs!(point(0.2));
    await vi.advanceTimersByTimeAsync(budget - 1);
    expect(made()).toBe(1);
    await vi.advanceTimersByTimeAsync(2);
    expect(made()).toBe(2);
    expect((await p)?.theta2Rad).toBe(0.2);
    second.dead = true;
    const c = client.run('cycle', CYCLE).result;
    await vi.advanceTimersByTimeAsync(simulatorJobs.cycle.budgetMs!(CYCLE) + 1);
    expect((await c)?.theta2Deg.length).toBe(37);
    expect(fallback.runs().map((r) => r.job)).toEqual(['cycle']);
    expect(modes).toEqual([
      ['worker', null],
      ['restarted', 'stopped'],
      ['main-thread', 'stopped'],
    ]);
    client.dispose();
  });

  it('solves on the main thread, with the same handlers, when no worker can start', async () => {
    const modes: [JobClientMode, JobClientModeReason | null][] = [];
    const client = createSolverClient({
      createWorker: () => {
        throw new Error('SecurityError: opaque origin');
      },
      onModeChange: (m, r) => modes.push([m, r]),
    });
    expect(client.mode).toBe('main-thread');
    expect((await client.run('cycle', { ...CYCLE, samples: 360 }).result)?.theta2Deg.length).toBe(361);
    await expect(client.run('point', { ...point(1), linkage: { ...L, r3: 0 } }).result).rejects.toThrow(/r3 .*got 0/);
    expect(modes).toEqual([['main-thread', 'unavailable']]);
    client.dispose();
  });
});
