import './AnalysisPanel.css';
import { memo } from 'react';
import type { Branch } from '../../solver/types';
import type { NrStart } from '../../shared/state/appState';
import { radToDeg, radToDeg180, radToDeg360 } from '../../solver/angles';
import { formatDeg, formatSci } from '../../shared/format';
import { grashofSumsText } from './grashofText';
import { formatInputRange } from '../../shared/state/inputRange';
import type { CycleResponse, PointResponse, TableResponse } from '../../shared/jobs/protocol';
import { useMessages } from '../../shared/i18n/MessagesContext';

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
            <span className={`badge ${c?.grashof ? 'badge-ok' : 'badge-warn'}`}>{verdict}</span>
          </dd>
        </div>
        <div className="fact">
          <dt>{t.linkageType}</dt>
          <dd data-testid="linkage-type">{c ? t.types[c.type] : '—'}</dd>
        </div>
        <div className="fact">
          <dt>{t.barker}</dt>
          <dd className="mono">{c ? c.barker : '—'}</dd>
        </div>
        <div className="fact fact-wide">
          <dt>{t.inputRange}</dt>
          <dd>{range}</dd>
        </div>
      </dl>
      <h3 className="subhead">{t.atTheta2(theta2)}</h3>
      <dl className="facts facts-grid">
        <div className="fact">
          <dt>θ3</dt>
          <dd className="mono">{pose ? deg(pose.theta3) : '—'}</dd>
        </div>
        <div className="fact">
          <dt>θ4</dt>
          <dd className="mono">{pose ? deg(pose.theta4) : '—'}</dd>
        </div>
        <div className="fact">
          <dt>{t.transmissionAngle}</dt>
          <dd className="mono">{pose ? `${formatDeg(radToDeg(pose.mu), 3)}°` : '—'}</dd>
        </div>
        <div className="fact">
          <dt>{t.status}</dt>
          <dd>
            {point ? (pose ? (nr ? t.newtonStatus[nr.status] : t.pointStatus.ok) : t.pointStatus.unreachable) : '—'}
          </dd>
        </div>
        <div className="fact">
          <dt>{t.nrIterations}</dt>
          <dd className="mono" data-testid="nr-iterations">
            {nr ? String(nr.iterations) : '—'}
          </dd>
        </div>
        <div className="fact">
          <dt>{t.residual}</dt>
          <dd className="mono">{nr ? formatSci(nr.residual) : '—'}</dd>
        </div>
        <div className="fact">
          <dt>{t.detJ}</dt>
          <dd className="mono">{nr ? formatSci(nr.detJ, 4) : '—'}</dd>
        </div>
        <div className="fact">
          <dt>{t.nrStartLabel}</dt>
          <dd>{nr ? (nr.start === 'continuation' ? t.nrContinuation : t.nrCold) : '—'}</dd>
        </div>
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
