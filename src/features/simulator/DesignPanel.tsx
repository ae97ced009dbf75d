import './DesignPanel.css';
import { memo, useMemo, useState } from 'react';
import type { Dispatch } from 'react';
import type { Action } from '../../shared/state/appState';
import type { DesignStop } from '../../shared/linkage/designFacts';
import { designFacts } from '../../shared/linkage/designFacts';
import type { DesignInfo } from './useDesignMetrics';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { NumberControl } from '../../shared/ui/NumberControl';

/** Props of DesignPanel: the design metrics (null when the lengths are refused), the μ band and the dispatcher. */
export interface DesignPanelProps {
  design: DesignInfo | null;
  muBandLoDeg: number;
  muBandHiDeg: number;
  dispatch: Dispatch<Action>;
  /** Embed with θ2 locked: no go-to buttons. */
  theta2Locked?: boolean;
  /** Embed layout: no band fields. */
  compact?: boolean;
}

interface GoToProps {
  what: string;
  at: DesignStop;
  testId: string;
  onGo: ((theta2Deg: number) => void) | null;
}

function GoTo({ what, at, testId, onGo }: GoToProps) {
  const t = useMessages();
  return (
    <dd className="goto-row">
      <span className="mono" data-testid={testId}>
        {t.designAt(at.theta2Text)}
      </span>
      {onGo ? (
        <button
          type="button"
          className="btn btn-small"
          aria-label={t.goToLabel(what, at.theta2Text)}
          onClick={() => onGo(at.theta2Deg)}
        >
          {t.goTo}
        </button>
      ) : null}
    </dd>
  );
}

function DesignPanelImpl({
  design,
  muBandLoDeg,
  muBandHiDeg,
  dispatch,
  theta2Locked = false,
  compact = false,
}: DesignPanelProps) {
  const t = useMessages();
  const facts = useMemo(() => (design ? designFacts(design.metrics, design.range) : null), [design]);
  const [bandError, setBandError] = useState(false);
  const onGo = theta2Locked
    ? null
    : (theta2Deg: number) => {
        dispatch({ type: 'setPlaying', playing: false });
        dispatch({ type: 'setTheta2', deg: theta2Deg });
      };
  const setBand = (loDeg: number, hiDeg: number) => {
    setBandError(!(loDeg < hiDeg));
    if (loDeg < hiDeg) dispatch({ type: 'setMuBand', loDeg, hiDeg });
  };
  const names = { extended: t.deadCentreExtended, folded: t.deadCentreFolded };

  return (
    <div className="design analysis">
      <dl className="facts">
        <div className="fact fact-wide">
          <dt>{t.designMuMin}</dt>
          <dd className="mono" data-testid="design-mu-min">
            {facts ? facts.muMinText : '—'}
          </dd>
          {facts ? <GoTo what={t.designMuMin} at={facts.muMinAt} testId="design-mu-min-at" onGo={null} /> : null}
        </div>
        <div className="fact fact-wide">
          <dt>{t.designMuMax}</dt>
          <dd className="mono" data-testid="design-mu-max">
            {facts ? facts.muMaxText : '—'}
          </dd>
          {facts ? <GoTo what={t.designMuMax} at={facts.muMaxAt} testId="design-mu-max-at" onGo={null} /> : null}
        </div>
        {facts?.deadCentres
          ? facts.deadCentres.map((dc) => (
              <div className="fact fact-wide" key={dc.kind} data-testid={`design-dc-${dc.kind}`}>
                <dt>{names[dc.kind]}</dt>
                <GoTo what={names[dc.kind]} at={dc} testId={`design-dc-${dc.kind}-at`} onGo={onGo} />
                <dd className="mono" data-testid={`design-dc-${dc.kind}-theta4`}>
                  {t.deadCentreTheta4(dc.theta4Text)}
                </dd>
              </div>
            ))
          : null}
        {facts?.swingText ? (
          <div className="fact">
            <dt>{t.swing}</dt>
            <dd className="mono" data-testid="design-swing">
              {facts.swingText}
            </dd>
          </div>
        ) : null}
        {facts?.timeRatioText ? (
          <div className="fact">
            <dt>{t.timeRatio}</dt>
            <dd className="mono" data-testid="design-time-ratio">
              {facts.timeRatioText}
            </dd>
          </div>
        ) : null}
        {facts
          ? facts.limits.map((at, i) => (
              <div className="fact fact-wide" key={`limit-${i}`}>
                <dt>{`${t.inputLimit} ${i + 1}`}</dt>
                <GoTo what={`${t.inputLimit} ${i + 1}`} at={at} testId={`design-limit-${i}`} onGo={onGo} />
              </div>
            ))
          : null}
      </dl>
      {facts && !facts.deadCentres && facts.limits.length === 0 ? <p className="note">{t.noDeadCentres}</p> : null}
      {!compact ? (
        <div className="band-fields" role="group" aria-label={t.muBand}>
          <h3 className="subhead">{t.muBand}</h3>
          <NumberControl
            field="muBandLo"
            value={muBandLoDeg}
            min={0}
            max={180}
            step={1}
            unit="°"
            onCommit={(v) => setBand(v, muBandHiDeg)}
          />
          <NumberControl
            field="muBandHi"
            value={muBandHiDeg}
            min={0}
            max={180}
            step={1}
            unit="°"
            onCommit={(v) => setBand(muBandLoDeg, v)}
          />
          {bandError ? (
            <p className="note note-error" role="alert">
              {t.muBandOrder}
            </p>
          ) : null}
        </div>
      ) : null}
    </div>
  );
}

/**
 * The design metrics panel: transmission-angle extremes with their θ2, the dead centres (with go-to buttons),
 * the rocker's swing and the time ratio of a crank-rocker, a rocking input's limits, and the usable μ band.
 */
export const DesignPanel = memo(DesignPanelImpl);
