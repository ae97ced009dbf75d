import { GifReader } from 'omggif';
import { describe, expect, it } from 'vitest';
import { JobClient, JobError } from '../../../../src/shared/jobs/jobClient';
import { createMainThreadWorker } from '../../../../src/shared/jobs/mainThread';
import { gifJobs } from '../../../../src/features/export/animation/gifJobs';
import { createGifSession } from '../../../../src/features/export/animation/gifSession';
import { FakeWorker } from '../../../shared/jobs/fakeWorker';

const W = 4;
const H = 3;

/** A W x H RGBA frame of one colour. */
function solid(r: number, g: number, b: number): ArrayBuffer {
  const px = new Uint8ClampedArray(W * H * 4);
  for (let i = 0; i < px.length; i += 4) px.set([r, g, b, 255], i);
  return px.buffer;
}

const RED = [255, 0, 0];
const BLUE = [0, 0, 255];

/** Encodes red then blue through a client of the GIF jobs; resolves to the decoded file and the frames sent. */
async function encodeTwo(client: JobClient<typeof gifJobs>) {
  const ready = await client.run('begin', {
    width: W,
    height: H,
    loop: true,
    samples: [solid(255, 0, 0), solid(0, 0, 255)],
  }).result;
  const frames = [solid(255, 0, 0), solid(0, 0, 255)];
  const done = await Promise.all(frames.map((rgba, index) => client.run('frame', { index, rgba, delayCs: 5 }).result));
  const file = await client.run('finish', {}).result;
  const reader = new GifReader(new Uint8Array(file!.bytes));
  const pixels = [0, 1].map((k) => {
    const out = new Uint8Array(W * H * 4);
    reader.decodeAndBlitFrameRGBA(k, out);
    return Array.from(out.slice(0, 3));
  });
  return { ready, done, reader, pixels, frames };
}

describe('the GIF jobs through the job kit', () => {
  it('round-trips an encode through a worker: palette, frames moved not copied, the file back', async () => {
    const w = new FakeWorker(createGifSession(), true);
    const client = new JobClient(gifJobs, { createWorker: () => w, restarts: 0 });
    const { ready, done, reader, pixels, frames } = await encodeTwo(client);
    expect(ready?.colors).toBeGreaterThanOrEqual(2);
    expect(done).toEqual([{ index: 0 }, { index: 1 }]);
    expect([reader.width, reader.height, reader.numFrames()]).toEqual([W, H, 2]);
    expect(reader.frameInfo(1).delay).toBe(5);
    expect(pixels).toEqual([RED, BLUE]);
    // The frames' pixels moved to the worker; the palette samples were copied (the fallback may need them).
    expect(frames.map((f) => f.byteLength)).toEqual([0, 0]);
    expect(w.transfers.map((t) => t.length)).toEqual([0, 1, 1, 0]);
    // The file's bytes came back moved too.
    expect(w.answerTransfers.at(-1)).toHaveLength(1);
    client.dispose();
  });

  it('encodes the same file on the main thread, from the same handlers', async () => {
    const client = new JobClient(gifJobs, {
      createWorker: () => {
        throw new Error('no module worker here');
      },
      createFallback: () => createMainThreadWorker(async () => createGifSession()),
    });
    expect(client.mode).toBe('main-thread');
    const { pixels, reader } = await encodeTwo(client);
    expect(reader.numFrames()).toBe(2);
    expect(pixels).toEqual([RED, BLUE]);
    client.dispose();
  });

  it('answers a call out of order with a typed error naming the job', async () => {
    const w = new FakeWorker(createGifSession(), true);
    const client = new JobClient(gifJobs, { createWorker: () => w });
    const err = await client.run('frame', { index: 0, rgba: solid(0, 0, 0), delayCs: 5 }).result.catch((e) => e);
    expect(err).toBeInstanceOf(JobError);
    expect((err as JobError).response).toMatchObject({ job: 'frame', message: 'a frame came before begin' });
    await expect(client.run('finish', {}).result).rejects.toThrow('finish came before begin');
    client.dispose();
  });
});
