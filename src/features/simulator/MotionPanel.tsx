import './AnalysisPanel.css';
import { memo } from 'react';
import { radToDeg360 } from '../../solver/angles';
import { formatDeg } from '../../shared/format';
import type { FrameMotion } from '../../shared/linkage/frameMotion';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { Fact } from './Fact';
import { motionFacts } from './motionFacts';

/** Props of MotionPanel: this frame's motion (null when the linkage does not assemble) and its theta2 (radians). */
export interface MotionPanelProps {
  motion: FrameMotion | null;
  theta2Rad: number;
  /** The app's length unit, shown in the speeds (mm/s); default the generic length/s. */
  lengthUnit?: string;
}

function MotionPanelImpl({ motion, theta2Rad, lengthUnit }: MotionPanelProps) {
  const t = useMessages();
  const facts = motion ? motionFacts(motion, t, lengthUnit) : [];
  return (
    <div className="motion" data-limit={motion?.limit ? 'true' : 'false'}>
      <h3 className="subhead">{t.motionAt(formatDeg(radToDeg360(theta2Rad), 2))}</h3>
      {motion ? (
        <dl className="facts facts-grid">
          {facts.map((f) => (
            <Fact
              key={f.key}
              label={f.label}
              wide={f.key.startsWith('v') || f.key === 'aP'}
              mono
              testId={`motion-${f.key}`}
            >
              {f.value}
            </Fact>
          ))}
        </dl>
      ) : (
        <p className="note">{t.motionNoPose}</p>
      )}
      <p className="footnote">{t.motionNote}</p>
    </div>
  );
}

/** Velocity and acceleration at the current θ2: ω3, ω4, α3, α4, speeds of A, B, P and P's acceleration with directions. */
export const MotionPanel = memo(MotionPanelImpl);
