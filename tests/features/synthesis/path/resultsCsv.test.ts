import { csvParseRows } from 'd3-dsv';
import { describe, expect, it } from 'vitest';
import { RESULTS_CSV_COLUMNS, resultsToCsv } from '../../../../src/features/synthesis/path/resultsCsv';
import type { PathSolution } from '../../../../src/synthesis/types';

const solution = (k: number): PathSolution => ({
  design: {
    links: { r1: 6 + k, r2: 2, r3: 5, r4: 5.5 },
    branch: k % 2 ? 'crossed' : 'open',
    O2: { x: -1.25, y: 0.1 + 0.2 },
    groundAngle: Math.PI / 6,
    pDist: 2.5,
    pAngle: -Math.PI / 2,
  },
  theta2: [0, 1],
  error: 1.5e-30 * (k + 1),
  maxDistance: 3e-16,
});

describe('resultsToCsv', () => {
  it('has exactly the issue’s columns, in order', () => {
    expect(resultsToCsv([]).trim()).toBe(
      'rank,error,max_distance,r1,r2,r3,r4,o2x,o2y,ground_deg,p_dist,p_angle_deg,branch',
    );
    expect(RESULTS_CSV_COLUMNS).toHaveLength(13);
  });

  it('writes one row per candidate with every number exact and the angles in degrees', () => {
    const rows = csvParseRows(resultsToCsv([solution(0), solution(1)]).trim());
    expect(rows).toHaveLength(3);
    const [, first, second] = rows;
    expect(first[0]).toBe('1');
    expect(second[0]).toBe('2');
    expect(Number(first[1])).toBe(1.5e-30);
    expect(Number(first[3])).toBe(6);
    expect(Number(second[3])).toBe(7);
    expect(Number(first[8])).toBe(0.1 + 0.2);
    // 30° and -90° read back to the degree's last bit: the conversion is one multiplication.
    expect(Number(first[9])).toBeCloseTo(30, 12);
    expect(Number(first[11])).toBeCloseTo(-90, 12);
    expect(first[12]).toBe('open');
    expect(second[12]).toBe('crossed');
  });
});
