import type { Messages } from '../../../shared/i18n/messages';
import { radToDeg } from '../../../solver';
import { formatDeg, formatNumber } from '../../../shared/format';
import type { MotionMessages } from './motionMessages';
import type { MotionCandidate } from './motionSolve';

/** Props of MotionFacts: the design shown and the texts. */
export interface MotionFactsProps {
  candidate: MotionCandidate;
  mt: MotionMessages;
  t: Messages;
}

/** Six or more poses: the design's error at each pose (position, length unit; angle, degrees). */
function PoseErrorTable({ candidate, mt }: { candidate: MotionCandidate; mt: MotionMessages }) {
  if (!candidate.errors) return null;
  return (
    <>
      <h4 className="synmode-subtitle">{mt.errorsTitle}</h4>
      <table className="synmode-table" data-testid="motion-errors">
        <caption className="sr-only">{mt.errorsCaption}</caption>
        <thead>
          <tr>
            <th scope="col">{mt.columnPose}</th>
            <th scope="col">{mt.columnPositionError}</th>
            <th scope="col">{mt.columnAngleError}</th>
          </tr>
        </thead>
        <tbody>
          {candidate.errors.map((e, i) => (
            <tr key={i} data-position={e.position} data-angle={e.angle}>
              <td>{i + 1}</td>
              <td>{formatNumber(e.position, 3)}</td>
              <td>{formatDeg(radToDeg(e.angle), 2)}</td>
            </tr>
          ))}
        </tbody>
      </table>
    </>
  );
}

/** The design's lengths, its type and its checks in words (order, branch and Grashof defects, or none); the error at each pose for six or more. */
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
      <PoseErrorTable candidate={candidate} mt={mt} />
    </div>
  );
}
