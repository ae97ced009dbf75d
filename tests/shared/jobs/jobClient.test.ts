import { afterEach, describe, expect, it, vi } from 'vitest';
import { JobClient, JobError } from '../../../src/shared/jobs/jobClient';
import type { JobClientMode, JobClientModeReason, JobClientOptions } from '../../../src/shared/jobs/jobClient';
import { createMainThreadWorker } from '../../../src/shared/jobs/mainThread';
import { FakeWorker, flush } from './fakeWorker';
import { toyHandlers, toyJobs, toyStats } from './toyJobs';

const WATCHDOG = { startMs: 1000, callMs: 100 };

/** A client of the toy table over the given worker (or workers made in turn), recording its modes. */
function setup(workers: FakeWorker[], options: Partial<JobClientOptions> = {}) {
  const modes: [JobClientMode, JobClientModeReason | null][] = [];
  let made = 0;
  const fallback = new FakeWorker(toyHandlers, true);
  const client = new JobClient(toyJobs, {
    createWorker: () => workers[made++],
    createFallback: () => fallback,
    watchdog: WATCHDOG,
    onModeChange: (m, r) => modes.push([m, r]),
    ...options,
  });
  return { client, modes, made: () => made, fallback };
}

afterEach(() => {
  vi.useRealTimers();
});

describe('JobClient latest wins', () => {
  it('keeps one call in flight and one waiting per channel, and delivers the answer in flight', async () => {
    const w = new FakeWorker(toyHandlers);
    const { client } = setup([w]);
    const results: (number | null)[] = [];
    const all = [1, 2, 3, 4, 5].map((n) => client.run('echo', { n }).result.then((r) => results.push(r ? r.n : null)));
    expect(w.received).toHaveLength(1);
    await w.deliver();
    // Only the newest waiting call is sent next; the ones in between were never sent.
    expect(w.runs().map((r) => (r.params as { n: number }).n)).toEqual([1, 5]);
    await w.deliver();
    await Promise.all(all);
    expect(results.filter((r) => r !== null)).toEqual([1, 5]);
    expect(results).toHaveLength(5);
    client.dispose();
  });

  it('drops a call in flight when its job says so: it resolves to null at once and the worker is told', async () => {
    const w = new FakeWorker(toyHandlers);
    const { client } = setup([w]);
    const first = client.run('sum', { xs: new Float64Array([1, 2]) });
    const second = client.run('sum', { xs: new Float64Array([3, 4]) });
    expect(await first.result).toBeNull();
    expect(w.received.map((r) => r.type)).toEqual(['run', 'cancel']);
    w.deliverAll();
    await flush();
    w.deliverAll();
    expect((await second.result)?.total).toBe(7);
    client.dispose();
  });

  it('keeps channels independent: the same job on two channels runs both', async () => {
    const w = new FakeWorker(toyHandlers, true);
    const { client } = setup([w]);
    const a = client.run('sum', { xs: new Float64Array([1]) }, { channel: 'summary' });
    const b = client.run('sum', { xs: new Float64Array([2]) }, { channel: 'export' });
    expect([(await a.result)?.total, (await b.result)?.total]).toEqual([1, 2]);
    client.dispose();
  });

  it('sends every call of a queue job at once and answers each', async () => {
    const w = new FakeWorker(toyHandlers);
    const { client } = setup([w]);
    const runs = [0, 1, 2].map((i) => client.run('step', { i }));
    expect(w.runs()).toHaveLength(3);
    w.deliverAll();
    expect(await Promise.all(runs.map((r) => r.result))).toEqual([{ i: 0 }, { i: 1 }, { i: 2 }]);
    client.dispose();
  });
});

describe('JobClient cancel and progress', () => {
  it('passes progress on and resolves with the result', async () => {
    const w = new FakeWorker(toyHandlers, true);
    const { client } = setup([w]);
    const seen: string[] = [];
    const run = client.run('slow', { stages: 3 }, { onProgress: (f, s) => seen.push(`${f.toFixed(2)} ${s}`) });
    expect(await run.result).toEqual({ stages: 3 });
    expect(seen).toEqual(['0.00 stage 0', '0.33 stage 1', '0.67 stage 2']);
    client.dispose();
  });

  it('cancel() resolves to null at once, aborts the handler’s signal, and no progress follows', async () => {
    const w = new FakeWorker(toyHandlers, true);
    const { client } = setup([w]);
    const seen: number[] = [];
    toyStats.slowStages = 0;
    const run = client.run('slow', { stages: 1000 }, { onProgress: (f) => seen.push(f) });
    await new Promise((r) => setTimeout(r, 5));
    run.cancel();
    const after = seen.length;
    expect(await run.result).toBeNull();
    expect(w.received.map((r) => r.type)).toEqual(['run', 'cancel']);
    await new Promise((r) => setTimeout(r, 20));
    expect(seen).toHaveLength(after);
    expect(toyStats.slowStages).toBeLessThan(1000);
    client.dispose();
  });

  it('passes on no progress of a cancelled call that the worker has not yet seen cancelled', async () => {
    const w = new FakeWorker(toyHandlers);
    const { client } = setup([w]);
    const seen: number[] = [];
    const run = client.run('slow', { stages: 5 }, { onProgress: (f) => seen.push(f) });
    await w.deliver();
    expect(seen).toEqual([0]);
    run.cancel();
    // The cancel waits in the channel: the handler goes on reporting, and the client keeps it to itself.
    await new Promise((r) => setTimeout(r, 20));
    expect(seen).toEqual([0]);
    client.dispose();
  });

  it('a waiting call that is cancelled is never sent', async () => {
    const w = new FakeWorker(toyHandlers);
    const { client } = setup([w]);
    client.run('slow', { stages: 1 });
    const waiting = client.run('slow', { stages: 2 });
    expect(w.received.map((r) => r.type)).toEqual(['run', 'cancel']);
    waiting.cancel();
    expect(await waiting.result).toBeNull();
    w.deliverAll();
    await new Promise((r) => setTimeout(r, 5));
    expect(w.runs().map((r) => (r.params as { stages: number }).stages)).toEqual([1]);
    client.dispose();
  });

  it('an aborted signal cancels the call, before or after it is sent', async () => {
    const w = new FakeWorker(toyHandlers, true);
    const { client } = setup([w]);
    const ac = new AbortController();
    const run = client.run('slow', { stages: 1000 }, { signal: ac.signal });
    ac.abort();
    expect(await run.result).toBeNull();
    const early = client.run('echo', { n: 1 }, { signal: ac.signal });
    expect(await early.result).toBeNull();
    client.dispose();
  });

  it('a newer long job supersedes a running one: the old resolves to null and is cancelled, the new one runs', async () => {
    const w = new FakeWorker(toyHandlers, true);
    const { client } = setup([w]);
    const old = client.run('slow', { stages: 3 });
    const fresh = client.run('slow', { stages: 2 });
    expect(await old.result).toBeNull();
    expect(await fresh.result).toEqual({ stages: 2 });
    expect(w.received.map((r) => r.type)).toEqual(['run', 'cancel', 'run']);
    client.dispose();
  });
});

describe('JobClient transfer', () => {
  it('moves the params’ buffers the job names, and the answer’s buffers back', async () => {
    const w = new FakeWorker(toyHandlers, true);
    const { client } = setup([w]);
    const xs = new Float64Array([1, 2, 3]);
    const r = await client.run('sum', { xs }).result;
    expect(w.transfers[0]).toEqual([xs.buffer]);
    // Moved, not copied: the sender's array is detached.
    expect(xs.byteLength).toBe(0);
    expect(r?.total).toBe(6);
    expect(Array.from(r!.xs)).toEqual([2, 4, 6]);
    expect(w.answerTransfers[0]).toHaveLength(1);
    expect(w.transfers[0]).toHaveLength(1);
    client.dispose();
  });

  it('copies params of a job that names no buffers', async () => {
    const w = new FakeWorker(toyHandlers, true);
    const { client } = setup([w]);
    await client.run('echo', { n: 1 }).result;
    expect(w.transfers[0]).toEqual([]);
    client.dispose();
  });
});

describe('JobClient errors', () => {
  it('rejects with the handler’s message in a typed error naming the job; the channel keeps working', async () => {
    const w = new FakeWorker(toyHandlers, true);
    const { client } = setup([w]);
    const err = await client.run('fail', { message: 'r2 must be positive, got -1' }).result.catch((e: unknown) => e);
    expect(err).toBeInstanceOf(JobError);
    expect((err as JobError).message).toBe('r2 must be positive, got -1');
    expect((err as JobError).response).toMatchObject({ type: 'error', job: 'fail' });
    expect(await client.run('fail', { message: 'again' }).result.catch((e: Error) => e.message)).toBe('again');
    expect(await client.run('echo', { n: 2 }).result).toEqual({ n: 2 });
    client.dispose();
  });

  it('rejects a call whose params cannot be sent, and sends the next one', async () => {
    const w = new FakeWorker(toyHandlers, true);
    const { client } = setup([w]);
    const bad = client.run('echo', { n: 1, f: () => 1 } as unknown as { n: number });
    await expect(bad.result).rejects.toThrow(/echo could not be sent/);
    expect(await client.run('echo', { n: 2 }).result).toEqual({ n: 2 });
    client.dispose();
  });
});

describe('createMainThreadWorker', () => {
  it('answers in a later task, as a worker does, never inside postMessage', async () => {
    const stand = createMainThreadWorker(async () => toyHandlers);
    const got: unknown[] = [];
    stand.addEventListener('message', (e) => got.push((e as MessageEvent).data));
    await new Promise((r) => setTimeout(r, 0));
    stand.postMessage({ type: 'run', id: 1, job: 'echo', params: { n: 1 } });
    await flush();
    expect(got).toEqual([]);
    await vi.waitFor(() => expect(got).toEqual([{ type: 'result', id: 1, job: 'echo', value: { n: 1 } }]));
    stand.terminate();
  });
});

describe('JobClient watchdog', () => {
  it('restarts a worker that stops answering, once, then runs on the fallback', async () => {
    vi.useFakeTimers();
    const first = new FakeWorker(toyHandlers, true);
    const second = new FakeWorker(toyHandlers, true);
    const { client, modes, made, fallback } = setup([first, second]);
    expect((await client.run('echo', { n: 1 }).result)?.n).toBe(1);
    expect(client.mode).toBe('worker');
    first.dead = true;
    const p = client.run('echo', { n: 2 }).result;
    // The budget of the call alone: this worker has answered before, so no start-up time.
    await vi.advanceTimersByTimeAsync(WATCHDOG.callMs - 1);
    expect(made()).toBe(1);
    await vi.advanceTimersByTimeAsync(2);
    expect(made()).toBe(2);
    expect(first.terminated).toBe(true);
    expect((await p)?.n).toBe(2);
    expect([client.mode, client.reason]).toEqual(['restarted', 'stopped']);
    second.dead = true;
    const q = client.run('echo', { n: 3 }).result;
    await vi.advanceTimersByTimeAsync(WATCHDOG.callMs + 1);
    expect((await q)?.n).toBe(3);
    expect(fallback.runs().map((r) => r.job)).toEqual(['echo']);
    expect(modes).toEqual([
      ['worker', null],
      ['restarted', 'stopped'],
      ['main-thread', 'stopped'],
    ]);
    client.dispose();
  });

  it('gives a worker that never answered the start-up time on top of the budgets it holds', async () => {
    vi.useFakeTimers();
    const w = new FakeWorker(toyHandlers);
    const { client, made } = setup([w, new FakeWorker(toyHandlers, true)]);
    void client.run('echo', { n: 1 });
    void client.run('step', { i: 1 });
    await vi.advanceTimersByTimeAsync(WATCHDOG.startMs + 2 * 100 - 1);
    expect(made()).toBe(1);
    await vi.advanceTimersByTimeAsync(2);
    expect(made()).toBe(2);
    client.dispose();
  });

  it('restarts at once on a worker error, and resends only the newest call of a latest channel', async () => {
    const first = new FakeWorker(toyHandlers);
    const second = new FakeWorker(toyHandlers, true);
    const { client, modes } = setup([first, second]);
    const a = client.run('echo', { n: 1 });
    const b = client.run('echo', { n: 2 });
    first.error('boom');
    expect(first.terminated).toBe(true);
    expect(await a.result).toBeNull();
    expect((await b.result)?.n).toBe(2);
    expect(second.runs().map((r) => (r.params as { n: number }).n)).toEqual([2]);
    expect(modes).toEqual([['restarted', 'unavailable']]);
    client.dispose();
  });

  it('resends every queue call in flight, in order, after a restart', async () => {
    const first = new FakeWorker(toyHandlers);
    const second = new FakeWorker(toyHandlers, true);
    const { client } = setup([first, second]);
    const runs = [0, 1, 2].map((i) => client.run('step', { i }));
    first.error('crashed');
    expect(await Promise.all(runs.map((r) => r.result))).toEqual([{ i: 0 }, { i: 1 }, { i: 2 }]);
    expect(second.runs().map((r) => (r.params as { i: number }).i)).toEqual([0, 1, 2]);
    client.dispose();
  });

  it('lets a long job run as long as its progress keeps coming', async () => {
    vi.useFakeTimers();
    const w = new FakeWorker(toyHandlers, true);
    const { client, made } = setup([w]);
    // Ten stages of 400 ms: 4 s in all, eight times the job's 500 ms budget.
    const run = client.run('slow', { stages: 10, stageMs: 400 });
    await vi.advanceTimersByTimeAsync(4500);
    expect(await run.result).toEqual({ stages: 10 });
    expect(made()).toBe(1);
    client.dispose();
  });

  it('does not blame the worker when its own timer fires late (this thread was busy)', async () => {
    vi.useFakeTimers();
    const w = new FakeWorker(toyHandlers);
    const { client, made } = setup([w]);
    const p = client.run('echo', { n: 3 }).result;
    vi.setSystemTime(Date.now() + 5000);
    await vi.advanceTimersByTimeAsync(WATCHDOG.startMs + WATCHDOG.callMs + 1);
    expect(made()).toBe(1);
    await w.deliver();
    expect((await p)?.n).toBe(3);
    client.dispose();
  });

  it('runs on the fallback at once when no worker can start', async () => {
    const modes: [JobClientMode, JobClientModeReason | null][] = [];
    const client = new JobClient(toyJobs, {
      createWorker: () => {
        throw new Error('SecurityError: opaque origin');
      },
      createFallback: () => createMainThreadWorker(async () => toyHandlers),
      onModeChange: (m, r) => modes.push([m, r]),
    });
    expect(client.mode).toBe('main-thread');
    expect(await client.run('echo', { n: 4 }).result).toEqual({ n: 4 });
    await expect(client.run('fail', { message: 'bad' }).result).rejects.toThrow('bad');
    expect(modes).toEqual([['main-thread', 'unavailable']]);
    client.dispose();
  });

  it('without a fallback, fails every pending and later call with an error naming the job', async () => {
    const w = new FakeWorker(toyHandlers);
    const { client, modes } = setup([w], { createFallback: undefined, restarts: 0 });
    const a = client.run('echo', { n: 1 });
    w.error('script failed to load');
    await expect(a.result).rejects.toThrow(/no worker can run echo: worker error: script failed to load/);
    await expect(client.run('step', { i: 1 }).result).rejects.toBeInstanceOf(JobError);
    expect(modes).toEqual([['failed', 'unavailable']]);
    client.dispose();
  });

  it('resolves everything pending to null on dispose, and every later call', async () => {
    const w = new FakeWorker(toyHandlers);
    const { client } = setup([w]);
    const a = client.run('echo', { n: 1 });
    const b = client.run('echo', { n: 2 });
    client.dispose();
    expect([await a.result, await b.result]).toEqual([null, null]);
    expect(w.terminated).toBe(true);
    expect(await client.run('echo', { n: 3 }).result).toBeNull();
  });
});
