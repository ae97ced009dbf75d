import type { Messages } from '../../../shared/i18n/messages';
import { Segmented } from '../../../shared/ui/Segmented';
import type { MotionMessages } from './motionMessages';
import type { MotionCandidate } from './motionSolve';
import { MotionFacts } from './MotionFacts';

/** Props of MotionDesignCard: the design, the pose it is shown at, and what choosing a pose and Open do. */
export interface MotionDesignCardProps {
  chosen: MotionCandidate;
  shownPose: number;
  onShow: (pose: number) => void;
  onOpen: () => void;
  mt: MotionMessages;
  t: Messages;
}

/** The design found: its facts, the pose it is drawn at, and Open in simulator. */
export function MotionDesignCard({ chosen, shownPose, onShow, onOpen, mt, t }: MotionDesignCardProps) {
  return (
    <div className="synmode-design" data-testid="motion-design">
      <h3 className="section-title">{mt.designTitle}</h3>
      <MotionFacts candidate={chosen} mt={mt} t={t} />
      <Segmented
        legend={mt.shownAt}
        value={String(shownPose)}
        options={chosen.theta2.map((_, i) => ({ value: String(i), label: mt.poseName(i + 1) }))}
        onChange={(v) => onShow(Number(v))}
      />
      <button type="button" className="btn btn-primary" onClick={onOpen}>
        {mt.openInSimulator}
      </button>
    </div>
  );
}
