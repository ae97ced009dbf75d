import type { Messages } from '../../../shared/i18n/messages';
import type { FunctionMessages } from './functionMessages';
import type { FunctionDesign } from './functionSolve';
import { FunctionFacts } from './FunctionFacts';
import { PrecisionTable } from './PrecisionTable';

/** Props of FunctionDesignCard: the design, "Open in simulator" and the texts. */
export interface FunctionDesignCardProps {
  fd: FunctionDesign;
  onOpen: () => void;
  fm: FunctionMessages;
  t: Messages;
}

/** The design found: its facts, its precision points and Open in simulator. */
export function FunctionDesignCard({ fd, onOpen, fm, t }: FunctionDesignCardProps) {
  return (
    <div className="synmode-design">
      <h3 className="section-title">{fm.designTitle}</h3>
      <FunctionFacts fd={fd} fm={fm} t={t} />
      <h4 className="synmode-subtitle">{fm.precisionTitle}</h4>
      <PrecisionTable fd={fd} fm={fm} />
      <button type="button" className="btn btn-primary" onClick={onOpen}>
        {fm.openInSimulator}
      </button>
    </div>
  );
}
