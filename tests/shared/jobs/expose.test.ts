import { describe, expect, it } from 'vitest';
import { solverApi } from '../../../src/workers/api';
import { expose, transferablesOf } from '../../../src/shared/jobs/expose';
import type { Endpoint } from '../../../src/shared/jobs/expose';
import type { SolverApi, SolverResponse } from '../../../src/shared/jobs/protocol';

const L = { r1: 6, r2: 2, r3: 5, r4: 5 };
const C = { distance: 2.5, angleRad: Math.PI / 6 };
const SOLVER = { method: 'newton' as const, tol: null };
const CYCLE = { linkage: L, samples: 360, coupler: C, solver: SOLVER, branch: 'open' as const };

/** An endpoint that records what expose posts (and the transfer lists) and lets the test send requests. */
function endpoint() {
  const posted: { message: SolverResponse; transfer: Transferable[] }[] = [];
  let listener: ((e: MessageEvent) => void) | null = null;
  const ep: Endpoint = {
    postMessage: (message, transfer) => posted.push({ message, transfer }),
    addEventListener: (_type, l) => {
      listener = l;
    },
  };
  const send = async (data: unknown) => {
    listener?.({ data } as MessageEvent);
    // expose answers after awaiting the call: let its microtasks run.
    await new Promise((r) => setTimeout(r, 0));
  };
  return { ep, posted, send };
}

/** Every typed array under value (plain objects and arrays), found independently of transferablesOf. */
function typedArrays(value: unknown): ArrayBufferView[] {
  if (ArrayBuffer.isView(value)) return [value];
  if (value && typeof value === 'object') return Object.values(value).flatMap(typedArrays);
  return [];
}

describe('expose', () => {
  it('answers { type, id, value } with every buffer of the value in the transfer list', async () => {
    const { ep, posted, send } = endpoint();
    expose(solverApi, ep);
    const params = { ...CYCLE, otherBranch: true, curves: true };
    await send({ type: 'cycle', id: 4, params });
    expect(posted).toHaveLength(1);
    const { message, transfer } = posted[0];
    if (message.type !== 'cycle') throw new Error(message.type);
    expect(message.id).toBe(4);
    const arrays = typedArrays(message.value);
    // 2 branches x 7 arrays, 2 curves x 2 and the grid.
    expect(arrays).toHaveLength(2 * 7 + 2 * 2 + 1);
    for (const a of arrays) expect(transfer).toContain(a.buffer);
    expect(new Set(transfer).size).toBe(transfer.length);
  });

  it('moves the buffers across a real channel: the sender keeps none, the receiver gets the numbers', async () => {
    const value = { a: new Float64Array([1, 2, 3]), b: [{ c: new Int32Array([4]) }], d: 5 };
    const { port1, port2 } = new MessageChannel();
    const got = new Promise<typeof value>((resolve) => {
      port2.onmessage = (e) => resolve(e.data as typeof value);
    });
    port1.postMessage(value, transferablesOf(value));
    const received = await got;
    expect(value.a.byteLength).toBe(0);
    expect(value.b[0].c.byteLength).toBe(0);
    expect(Array.from(received.a)).toEqual([1, 2, 3]);
    expect(Array.from(received.b[0].c)).toEqual([4]);
    port1.close();
    port2.close();
  });

  it('labels a malformed request’s error with that request’s own type', async () => {
    const { ep, posted, send } = endpoint();
    expose(solverApi, ep);
    await send({ type: 'cycle', id: 1, params: { ...CYCLE, linkage: { ...L, r1: -2 }, otherBranch: false } });
    await send({ type: 'table', id: 2 });
    await send({ type: 'lab', id: 3, params: null });
    await send({ type: 'nope', id: 4, params: {} });
    await send({ id: 5 });
    await send(null);
    expect(posted.map((p) => p.message)).toEqual([
      { type: 'error', id: 1, requestType: 'cycle', message: expect.stringMatching(/r1 .*got -2/) },
      { type: 'error', id: 2, requestType: 'table', message: 'table request has no params' },
      { type: 'error', id: 3, requestType: 'lab', message: 'lab request has no params' },
      { type: 'error', id: 4, requestType: 'nope', message: 'unknown request type "nope"' },
      { type: 'error', id: 5, requestType: 'unknown', message: 'unknown request type undefined' },
      { type: 'error', id: -1, requestType: 'unknown', message: 'unknown request type undefined' },
    ]);
  });

  it('reports progress and stops a long call that is cancelled', async () => {
    let stages = 0;
    const api: SolverApi = {
      ...solverApi,
      async lab(_params, task) {
        for (let i = 0; i < 100; i++) {
          task.progress(i / 100, `stage ${i}`);
          stages++;
          await new Promise((r) => setTimeout(r, 0));
          if (task.cancelled()) return null;
        }
        throw new Error('not cancelled');
      },
    };
    const { ep, posted, send } = endpoint();
    expose(api, ep);
    await send({ type: 'lab', id: 9, params: { linkage: L, branch: 'open', stepDeg: 1 } });
    await send({ type: 'cancel', id: 9 });
    await new Promise((r) => setTimeout(r, 10));
    const last = posted[posted.length - 1].message;
    expect(last).toEqual({ type: 'lab', id: 9, value: null });
    expect(posted[0].message).toEqual({ type: 'progress', id: 9, fraction: 0, stage: 'stage 0' });
    expect(stages).toBeLessThan(10);
  });
});
