import type { Messages } from '../../../shared/i18n/messages';
import { formatNumber } from '../../../shared/format';
import type { FunctionMessages } from './functionMessages';
import type { FunctionCheck, FunctionDesign } from './functionSolve';
import { LARGE_ERROR_SHARE } from './functionSolve';

/** Props of FunctionFacts: the design and the texts. */
export interface FunctionFactsProps {
  fd: FunctionDesign;
  fm: FunctionMessages;
  t: Messages;
}

/** A check of the page's in words. */
export function checkText(c: FunctionCheck, fm: FunctionMessages): string {
  if (c.code === 'notMonotone') return fm.notMonotone(formatNumber(c.x, 4));
  return fm.largeError(formatNumber(100 * c.share, 3), formatNumber(100 * LARGE_ERROR_SHARE, 3));
}

/** The design's lengths, type, branch, largest error, defects and the page's checks in words. */
export function FunctionFacts({ fd, fm, t }: FunctionFactsProps) {
  const { links, branch, maxError, defects } = fd.result;
  const f = (v: number) => formatNumber(v, 5);
  const percent = (100 * maxError) / Math.abs(fd.y1 - fd.y0);
  const fine = defects.length === 0 && fd.checks.length === 0;
  return (
    <div className="synmode-facts" data-testid="function-facts">
      <p className="synmode-links">{fm.links(f(links.r1), f(links.r2), f(links.r3), f(links.r4))}</p>
      <p>{fm.typeLine(t.types[fd.type])}</p>
      <p>{fm.branchLine(branch === 'open' ? t.branchOpen : t.branchCrossed)}</p>
      <p data-testid="function-max-error" data-value={maxError}>
        {Number.isFinite(maxError) ? fm.maxError(formatNumber(maxError, 3), formatNumber(percent, 3)) : fm.maxErrorNone}
      </p>
      <h4 className="synmode-subtitle">{fm.defectsTitle}</h4>
      {!fine ? (
        <ul className="synmode-defects" data-testid="function-defects">
          {fd.checks.map((c) => (
            <li key={c.code} data-defect={c.code}>
              {checkText(c, fm)}
            </li>
          ))}
          {defects.map((d) => (
            <li key={d} data-defect={d}>
              {fm.defectWords[d]}
            </li>
          ))}
        </ul>
      ) : (
        <p className="synmode-ok" data-testid="function-defects">
          {fm.noDefects}
        </p>
      )}
    </div>
  );
}
