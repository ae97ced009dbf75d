import { describe, expect, it } from 'vitest';
import { pathStageText, readPathStage } from '../../../src/features/synthesis/jobs';
import type { PathCandidate } from '../../../src/synthesis';

const candidate: PathCandidate = { sigma: -1, dir: 1, x: [0.1, 1 / 3, -2e-300, Math.PI, 5e-324], f: 1e-29, round: 7 };

describe('pathStageText', () => {
  it('carries the best Σd² and the candidates across the worker boundary double for double', () => {
    const back = readPathStage(pathStageText({ fraction: 0.5, best: 0.1 + 0.2, candidates: [candidate] }));
    expect(back.best).toBe(0.1 + 0.2);
    expect(back.candidates).toEqual([candidate]);
    for (let i = 0; i < candidate.x.length; i++) expect(Object.is(back.candidates[0].x[i], candidate.x[i])).toBe(true);
  });

  it('says "none yet" for an infinite best, and reads a text of another kind as nothing found', () => {
    expect(readPathStage(pathStageText({ fraction: 0, best: Infinity }))).toEqual({ best: Infinity, candidates: [] });
    expect(readPathStage('0.25')).toEqual({ best: 0.25, candidates: [] });
    expect(readPathStage('not json')).toEqual({ best: Infinity, candidates: [] });
  });
});
