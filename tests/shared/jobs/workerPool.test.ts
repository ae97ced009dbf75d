import { describe, expect, it } from 'vitest';
import { JobClient } from '../../../src/shared/jobs/jobClient';
import { createWorkerPool, defaultPoolSize } from '../../../src/shared/jobs/workerPool';
import { FakeWorker } from './fakeWorker';
import { toyHandlers, toyJobs } from './toyJobs';

describe('createWorkerPool', () => {
  it('spreads the parts of a split job over its workers and answers each part', async () => {
    const workers: FakeWorker[] = [];
    const pool = createWorkerPool((i) => {
      workers[i] = new FakeWorker(toyHandlers);
      return new JobClient(toyJobs, { createWorker: () => workers[i] });
    }, 3);
    const parts = [0, 1, 2, 3, 4, 5].map((i) => pool.run('step', { i }).result);
    expect(workers.map((w) => w.runs().map((r) => (r.params as { i: number }).i))).toEqual([
      [0, 3],
      [1, 4],
      [2, 5],
    ]);
    for (const w of workers) w.deliverAll();
    expect(await Promise.all(parts)).toEqual([0, 1, 2, 3, 4, 5].map((i) => ({ i })));
    pool.dispose();
    expect(workers.every((w) => w.terminated)).toBe(true);
  });

  it('sends the next part to the worker that has fewest pending', async () => {
    const workers: FakeWorker[] = [];
    const pool = createWorkerPool((i) => {
      workers[i] = new FakeWorker(toyHandlers, i === 1);
      return new JobClient(toyJobs, { createWorker: () => workers[i] });
    }, 2);
    // Part 0 goes to worker 0, which holds it unanswered; worker 1 answers part 1 at once, so part 2 goes there too.
    void pool.run('step', { i: 0 });
    await pool.run('step', { i: 1 }).result;
    await pool.run('step', { i: 2 }).result;
    expect(workers[0].runs()).toHaveLength(1);
    expect(workers[1].runs()).toHaveLength(2);
    pool.dispose();
  });

  it('refuses a size that is not a whole number of workers, and sizes to the cores but one by default', () => {
    expect(() => createWorkerPool(() => null as never, 0)).toThrow(/size .*got 0/);
    expect(defaultPoolSize()).toBeGreaterThanOrEqual(1);
  });
});
