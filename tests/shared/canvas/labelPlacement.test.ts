import { describe, expect, it } from 'vitest';
import type { LabelRequest, Obstacle } from '../../../src/shared/canvas/labelPlacement';
import { placeLabels } from '../../../src/shared/canvas/labelPlacement';

const BOUNDS = { x: 0, y: 0, width: 200, height: 100 };

function req(id: string, candidates: { x: number; y: number }[], required = false): LabelRequest<string> {
  return { id, width: 20, height: 10, candidates, required };
}

describe('placeLabels', () => {
  it('gives the first free candidate, and the next one to a later label that would overlap it', () => {
    const r = placeLabels(
      [
        req('a', [{ x: 50, y: 50 }]),
        req('b', [
          { x: 55, y: 52 },
          { x: 90, y: 50 },
        ]),
      ],
      BOUNDS,
      [],
      [],
    );
    expect(r.placed.map((p) => [p.id, p.candidateIndex])).toEqual([
      ['a', 0],
      ['b', 1],
    ]);
    expect(r.placed[1].box).toEqual({ x: 80, y: 45, width: 20, height: 10 });
  });

  it('lets boxes touch but not overlap', () => {
    const r = placeLabels([req('a', [{ x: 50, y: 50 }]), req('b', [{ x: 70, y: 50 }])], BOUNDS, [], []);
    expect(r.dropped).toEqual([]);
  });

  it('skips candidates under an exclusion or across the bounds, and drops a label with nowhere to go', () => {
    const tools = { x: 170, y: 0, width: 30, height: 60 };
    const r = placeLabels(
      [
        req('a', [
          { x: 180, y: 20 },
          { x: 5, y: 50 },
          { x: 150, y: 20 },
        ]),
        req('b', [{ x: 185, y: 30 }]),
      ],
      BOUNDS,
      [tools],
      [],
    );
    expect(r.placed.map((p) => [p.id, p.candidateIndex])).toEqual([['a', 2]]);
    expect(r.dropped).toEqual(['b']);
  });

  it('prefers the candidate covering the least obstacle weight, not counting its own obstacles', () => {
    const obstacles: Obstacle[] = [
      { kind: 'rect', rect: { x: 40, y: 40, width: 10, height: 10 }, weight: 4 },
      { kind: 'segment', a: { x: 100, y: 0 }, b: { x: 100, y: 100 }, halfWidth: 2, weight: 1 },
      { kind: 'segment', a: { x: 140, y: 0 }, b: { x: 140, y: 100 }, halfWidth: 2, weight: 3, owner: 'a' },
    ];
    const r = placeLabels(
      [
        req('a', [
          { x: 45, y: 45 },
          { x: 100, y: 50 },
          { x: 140, y: 50 },
        ]),
      ],
      BOUNDS,
      [],
      obstacles,
    );
    expect(r.placed[0].candidateIndex).toBe(2);
    expect(r.placed[0].cost).toBe(0);
    const s = placeLabels(
      [
        req('s', [
          { x: 45, y: 45 },
          { x: 100, y: 50 },
          { x: 140, y: 50 },
        ]),
      ],
      BOUNDS,
      [],
      obstacles,
    );
    expect(s.placed[0].candidateIndex).toBe(1);
    expect(s.placed[0].cost).toBe(1);
  });

  it('places a required label at its first candidate when nothing is free', () => {
    const r = placeLabels([req('w', [{ x: 185, y: 20 }], true)], BOUNDS, [{ x: 170, y: 0, width: 30, height: 60 }], []);
    expect(r.placed[0].centre).toEqual({ x: 185, y: 20 });
  });
});
