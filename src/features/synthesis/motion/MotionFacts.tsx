import type { Messages } from '../../../shared/i18n/messages';
import { formatNumber } from '../../../shared/format';
import type { MotionMessages } from './motionMessages';
import type { MotionCandidate } from './motionSolve';

/** Props of MotionFacts: the design shown and the texts. */
export interface MotionFactsProps {
  candidate: MotionCandidate;
  mt: MotionMessages;
  t: Messages;
}

/** The design's lengths, its type and its checks in words (order, branch and Grashof defects, or none). */
export function MotionFacts({ candidate, mt, t }: MotionFactsProps) {
  const { links, O2, groundAngle } = candidate.design;
  const O4 = { x: O2.x + links.r1 * Math.cos(groundAngle), y: O2.y + links.r1 * Math.sin(groundAngle) };
  const f = (v: number) => formatNumber(v, 5);
  return (
    <div className="synmode-facts" data-testid="motion-facts">
      <p className="synmode-links" data-testid="motion-links">
        {mt.links(f(links.r1), f(links.r2), f(links.r3), f(links.r4))}
      </p>
      <p data-testid="motion-pivots" data-o2={`${O2.x},${O2.y}`} data-o4={`${O4.x},${O4.y}`}>
        {mt.pivotsLine(f(O2.x), f(O2.y), f(O4.x), f(O4.y))}
      </p>
      <p>{mt.typeLine(t.types[candidate.type])}</p>
      <h4 className="synmode-subtitle">{mt.defectsTitle}</h4>
      {candidate.defects.length ? (
        <ul className="synmode-defects" data-testid="motion-defects">
          {candidate.defects.map((d) => (
            <li key={d} data-defect={d}>
              {mt.defectWords[d]}
            </li>
          ))}
        </ul>
      ) : (
        <p className="synmode-ok" data-testid="motion-defects">
          {mt.noDefects}
        </p>
      )}
    </div>
  );
}
