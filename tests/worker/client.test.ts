import { describe, expect, it } from 'vitest';
import { SolverClient } from '../../src/worker/client';
import type { WorkerLike } from '../../src/worker/client';
import { handleRequest } from '../../src/worker/compute';
import type { SolverRequest, SolverResponse } from '../../src/worker/protocol';

const L = { r1: 6, r2: 2, r3: 5, r4: 5 };
const C = { distance: 2.5, angleRad: Math.PI / 6 };

/** A fake worker that holds requests until the test answers them, solving with the real compute. */
class FakeWorker implements WorkerLike {
  received: SolverRequest[] = [];
  private listener: ((e: Event) => void) | null = null;
  postMessage(message: SolverRequest): void {
    this.received.push(message);
  }
  addEventListener(type: string, listener: (e: Event) => void): void {
    if (type === 'message') this.listener = listener;
  }
  terminate(): void {}
  answer(i: number): void {
    const r: SolverResponse = handleRequest(this.received[i]).response;
    this.listener?.({ data: r } as unknown as Event);
  }
}

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
const CYCLE_NEEDS = { solver: SOLVER, branch: 'open' as const, otherBranch: true, curves: true, plotPixels: 0 };

describe('SolverClient', () => {
  it('keeps one request in flight and one queued: no backlog while a slider is dragged', async () => {
    const w = new FakeWorker();
    const client = new SolverClient({ createWorker: () => w });
    const results: (number | null)[] = [];
    const track = (p: Promise<{ theta2Rad: number } | null>) => p.then((r) => results.push(r ? r.theta2Rad : null));
    const all = [0.1, 0.2, 0.3, 0.4, 0.5].map((t) => track(client.requestPoint(point(t))));
    expect(w.received).toHaveLength(1);
    w.answer(0);
    await Promise.resolve();
    // The first answer is stale (newer requests exist); only the newest queued request is sent next.
    expect(w.received).toHaveLength(2);
    expect(w.received[1].type === 'point' && w.received[1].theta2Rad).toBe(0.5);
    w.answer(1);
    await Promise.all(all);
    expect(results.filter((r) => r !== null)).toEqual([0.5]);
    expect(results).toHaveLength(5);
    client.dispose();
  });

  it('always ends with the last value solved', async () => {
    const w = new FakeWorker();
    const client = new SolverClient({ createWorker: () => w });
    const first = client.requestPoint(point(1));
    w.answer(0);
    expect((await first)?.theta2Rad).toBe(1);
    const last = client.requestPoint(point(2));
    w.answer(1);
    expect((await last)?.theta2Rad).toBe(2);
    client.dispose();
  });

  it('keeps the cycle and point channels independent', async () => {
    const w = new FakeWorker();
    const client = new SolverClient({ createWorker: () => w });
    const c = client.requestCycle({ linkage: L, samples: 36, coupler: C, ...CYCLE_NEEDS });
    const p = client.requestPoint(point(1));
    expect(w.received.map((r) => r.type)).toEqual(['cycle', 'point']);
    w.answer(1);
    w.answer(0);
    expect((await p)?.type).toBe('point');
    expect((await c)?.type).toBe('cycle');
    client.dispose();
  });

  it('falls back to solving on the main thread when the worker cannot start', async () => {
    const modes: string[] = [];
    const client = new SolverClient({
      createWorker: () => {
        throw new Error('SecurityError: opaque origin');
      },
      onModeChange: (m) => modes.push(m),
    });
    expect(client.mode).toBe('main-thread');
    const r = await client.requestCycle({ linkage: L, samples: 360, coupler: C, ...CYCLE_NEEDS });
    expect(r?.theta2Deg.length).toBe(361);
    expect(modes).toEqual(['main-thread']);
    client.dispose();
  });

  it('falls back when the worker never answers', async () => {
    const w = new FakeWorker();
    const client = new SolverClient({ createWorker: () => w, startTimeoutMs: 10 });
    const r = await client.requestPoint(point(0.5));
    expect(client.mode).toBe('main-thread');
    expect(r?.pose).not.toBeNull();
    client.dispose();
  });

  it('rejects with the worker message for an error answer', async () => {
    const w = new FakeWorker();
    const client = new SolverClient({ createWorker: () => w });
    const p = client.requestPoint({ ...point(1), linkage: { r1: 6, r2: -1, r3: 5, r4: 5 } });
    w.answer(0);
    await expect(p).rejects.toThrow(/r2 must be a positive finite length, got -1/);
    client.dispose();
  });
});
