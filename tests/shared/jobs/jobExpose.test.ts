import { describe, expect, it } from 'vitest';
import { serveJobs, transferablesOf } from '../../../src/shared/jobs/jobExpose';
import type { Endpoint } from '../../../src/shared/jobs/jobExpose';
import type { AnyJobResponse } from '../../../src/shared/jobs/jobProtocol';
import { toyHandlers, toyStats } from './toyJobs';

/** An endpoint that records what serveJobs posts (and the transfer lists) and lets the test send requests. */
function endpoint() {
  const posted: { message: AnyJobResponse; transfer: Transferable[] }[] = [];
  let listener: ((e: MessageEvent) => void) | null = null;
  const ep: Endpoint = {
    postMessage: (message, transfer) => posted.push({ message, transfer }),
    addEventListener: (_type, l) => {
      listener = l;
    },
  };
  const send = async (data: unknown) => {
    listener?.({ data } as MessageEvent);
    // serveJobs answers after awaiting the handler: let its microtasks run.
    await new Promise((r) => setTimeout(r, 0));
  };
  return { ep, posted, send };
}

describe('serveJobs', () => {
  it('answers { type: result, id, job, value } with every buffer of the value in the transfer list', async () => {
    const { ep, posted, send } = endpoint();
    serveJobs(toyHandlers, ep);
    await send({ type: 'run', id: 4, job: 'sum', params: { xs: new Float64Array([1, 2]) } });
    expect(posted).toHaveLength(1);
    const { message, transfer } = posted[0];
    if (message.type !== 'result') throw new Error(message.type);
    expect(message).toMatchObject({ id: 4, job: 'sum', value: { total: 3 } });
    expect(transfer).toEqual([(message.value as { xs: Float64Array }).xs.buffer]);
  });

  it('labels a malformed request’s error with that request’s own job', async () => {
    const { ep, posted, send } = endpoint();
    serveJobs(toyHandlers, ep);
    await send({ type: 'run', id: 1, job: 'fail', params: { message: 'r1 must be positive, got -2' } });
    await send({ type: 'run', id: 2, job: 'echo' });
    await send({ type: 'run', id: 3, job: 'slow', params: null });
    await send({ type: 'run', id: 4, job: 'nope', params: {} });
    await send({ type: 'run', id: 5, job: 'toString', params: {} });
    await send({ type: 'echo', id: 6, job: 'echo', params: { n: 1 } });
    await send({ id: 7 });
    await send(null);
    expect(posted.map((p) => p.message)).toEqual([
      { type: 'error', id: 1, job: 'fail', message: 'r1 must be positive, got -2' },
      { type: 'error', id: 2, job: 'echo', message: 'echo request has no params' },
      { type: 'error', id: 3, job: 'slow', message: 'slow request has no params' },
      { type: 'error', id: 4, job: 'nope', message: 'unknown job "nope"' },
      // Only the table's own names: an object's inherited methods are not jobs.
      { type: 'error', id: 5, job: 'toString', message: 'unknown job "toString"' },
      { type: 'error', id: 6, job: 'echo', message: 'unknown request type "echo"' },
      { type: 'error', id: 7, job: 'unknown', message: 'unknown request type "unknown"' },
      { type: 'error', id: -1, job: 'unknown', message: 'unknown request type "unknown"' },
    ]);
  });

  it('reports progress and aborts a long call’s signal when it is cancelled', async () => {
    const { ep, posted, send } = endpoint();
    serveJobs(toyHandlers, ep);
    toyStats.slowStages = 0;
    await send({ type: 'run', id: 9, job: 'slow', params: { stages: 100 } });
    await send({ type: 'cancel', id: 9 });
    await new Promise((r) => setTimeout(r, 10));
    expect(posted[0].message).toEqual({ type: 'progress', id: 9, fraction: 0, stage: 'stage 0' });
    expect(posted[posted.length - 1].message).toEqual({ type: 'result', id: 9, job: 'slow', value: null });
    expect(toyStats.slowStages).toBeLessThan(10);
  });

  it('aborts every running call when stopped (the main-thread stand-in’s terminate)', async () => {
    const { ep, posted, send } = endpoint();
    const stop = serveJobs(toyHandlers, ep);
    await send({ type: 'run', id: 1, job: 'slow', params: { stages: 100 } });
    await send({ type: 'run', id: 2, job: 'slow', params: { stages: 100 } });
    stop();
    await new Promise((r) => setTimeout(r, 10));
    const results = posted.filter((p) => p.message.type === 'result').map((p) => p.message);
    expect(results).toEqual([
      { type: 'result', id: 1, job: 'slow', value: null },
      { type: 'result', id: 2, job: 'slow', value: null },
    ]);
  });
});

describe('transferablesOf', () => {
  it('finds bare buffers and those under typed arrays, once each, in plain objects and arrays', () => {
    const shared = new Float64Array(2);
    const bytes = new ArrayBuffer(4);
    const value = {
      a: shared,
      b: [shared, new Int32Array(1)],
      c: { bytes },
      d: 5,
      e: new Map([[1, new Uint8Array(1)]]),
    };
    const list = transferablesOf(value);
    expect(list).toHaveLength(3);
    expect(list).toContain(shared.buffer);
    expect(list).toContain(bytes);
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
});
