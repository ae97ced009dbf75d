import { describe, expect, it } from 'vitest';
import { ninePointSynthesis } from '../../../../src/synthesis';
import { placedJoints } from '../../../../src/synthesis/placed';
import { cognateFollowers, cognatePoses } from '../../../../src/features/synthesis/ninePoint/nineCognates';
import { cognateDesign } from '../../../../src/features/synthesis/ninePoint/nineClassFacts';
import { KNOWN, KNOWN_POINTS, KNOWN_THETA2, startIndexOf } from '../../../synthesis/ninePointFixtures';

const dist = (p: { x: number; y: number }, q: { x: number; y: number }) => Math.hypot(p.x - q.x, p.y - q.y);

describe('cognates moving with the chosen linkage', () => {
  it('puts both other cognates on its coupler point, as closed four-bars, over a whole turn', async () => {
    const i = await startIndexOf(KNOWN_POINTS, KNOWN, KNOWN_THETA2[0]);
    const r = await ninePointSynthesis(KNOWN_POINTS, { paths: { start: i, end: i + 1 } });
    const cls = r.classes[0];
    for (const moving of cls.cognates) {
      const followers = cognateFollowers(moving, cls.cognates);
      expect(followers.length).toBe(2);
      const d = cognateDesign(moving);
      let drawn = 0;
      for (let k = 0; k < 90; k++) {
        const pose = placedJoints(d, d.theta2[0] + (k * 2 * Math.PI) / 90);
        if (!pose) continue;
        const poses = cognatePoses(pose, followers);
        expect(poses.length).toBe(2);
        followers.forEach((f, n) => {
          const q = poses[n];
          const { r1, r2, r3, r4 } = f.cognate.links;
          // The oracle: the same coupler point, and every link of the cognate at its length.
          expect(dist(q.P, pose.P)).toBeLessThan(1e-9);
          expect(Math.abs(dist(q.O2, q.O4) - r1)).toBeLessThan(1e-9);
          expect(Math.abs(dist(q.O2, q.A) - r2)).toBeLessThan(1e-9);
          expect(Math.abs(dist(q.A, q.B) - r3)).toBeLessThan(1e-9);
          expect(Math.abs(dist(q.B, q.O4) - r4)).toBeLessThan(1e-9);
        });
        drawn++;
      }
      expect(drawn).toBeGreaterThan(10);
    }
  });
});
