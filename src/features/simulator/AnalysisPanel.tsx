import './AnalysisPanel.css';
import { memo } from 'react';
import type { Branch } from '../../solver/types';
import type { NrStart } from '../../shared/state/appState';
import { radToDeg, radToDeg180, radToDeg360 } from '../../solver/angles';
import { formatDeg, formatSci } from '../../shared/format';
import { grashofSumsText } from './grashofText';
import { formatInputRange } from '../../shared/state/inputRange';
import type { CycleResponse, PointResponse, TableResponse } from '../../shared/solution';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { Fact } from './Fact';

/** Props of AnalysisPanel: the latest cycle and point answers, the branch and the chosen NR start. */
export interface AnalysisPanelProps {
  cycle: CycleResponse | null;
  /** The full n-point table of the branch (the cycle summary counts its rows); null until it arrives. */
  table: TableResponse | null;
  point: PointResponse | null;
  branch: Branch;
  nrStart: NrStart;
}

function AnalysisPanelImpl({ cycle, table, point, branch, nrStart }: AnalysisPanelProps) {
  const t = useMessages();
  const c = cycle?.classification;
  const verdict = !c ? '—' : c.type === 'change-point' ? t.grashofChangePoint : c.grashof ? t.grashofYes : t.grashofNo;
  const range = c ? formatInputRange(c.inputRange, t) : '—';
  const nr = point ? (nrStart === 'continuation' ? (point.continuation ?? point.cold) : point.cold) : null;
  const pose = point?.pose ?? null;
  const theta2 = point ? formatDeg(radToDeg360(point.theta2Rad), 2) : '—';
  const deg = (rad: number) => `${formatDeg(radToDeg180(rad), 3)}°`;

  return (
    <div className="analysis">
      <dl className="facts">
        <div className="fact fact-wide">
          <dt>{t.grashofCheck}</dt>
          <dd>
            <span className="mono" data-testid="grashof-sums">
              {c ? grashofSumsText(c) : 'S + L = — P + Q = —'}
            </span>
            <span className={`badge ${c?.grashof ? 'badge-ok' : 'badge-warn'}`} data-testid="grashof-verdict">
              {verdict}
            </span>
          </dd>
        </div>
        <Fact label={t.linkageType} testId="linkage-type">
          {c ? t.types[c.type] : '—'}
        </Fact>
        <Fact label={t.barker} mono testId="barker">
          {c ? c.barker : '—'}
        </Fact>
        <Fact label={t.inputRange} wide testId="input-range">
          {range}
        </Fact>
      </dl>
      <h3 className="subhead">{t.atTheta2(theta2)}</h3>
      <dl className="facts facts-grid">
        <Fact label="θ3" mono testId="analysis-theta3">
          {pose ? deg(pose.theta3) : '—'}
        </Fact>
        <Fact label="θ4" mono testId="analysis-theta4">
          {pose ? deg(pose.theta4) : '—'}
        </Fact>
        <Fact label={t.transmissionAngle} mono testId="analysis-mu">
          {pose ? `${formatDeg(radToDeg(pose.mu), 3)}°` : '—'}
        </Fact>
        <Fact label={t.status}>
          {point ? (pose ? (nr ? t.newtonStatus[nr.status] : t.pointStatus.ok) : t.pointStatus.unreachable) : '—'}
        </Fact>
        <Fact label={t.nrIterations} mono testId="nr-iterations">
          {nr ? String(nr.iterations) : '—'}
        </Fact>
        <Fact label={t.residual} mono>
          {nr ? formatSci(nr.residual) : '—'}
        </Fact>
        <Fact label={t.detJ} mono>
          {nr ? formatSci(nr.detJ, 4) : '—'}
        </Fact>
        <Fact label={t.nrStartLabel}>{nr ? (nr.start === 'continuation' ? t.nrContinuation : t.nrCold) : '—'}</Fact>
      </dl>
      {table && table.branch === branch ? (
        <p className="note">
          {t.cycleSummary(String(table.okCount), String(table.theta2Deg.length), String(table.totalIterations))}
        </p>
      ) : null}
    </div>
  );
}

/** The numbers panel: S + L against P + Q, type and Barker class, input range, and NR figures at theta2. */
export const AnalysisPanel = memo(AnalysisPanelImpl);
