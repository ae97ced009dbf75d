import './DesignPanel.css';
import { memo, useMemo, useState } from 'react';
import type { Dispatch } from 'react';
import type { Action } from '../../shared/state/appState';
import type { DesignFacts, DesignStop } from '../../shared/linkage/designFacts';
import { designFacts } from '../../shared/linkage/designFacts';
import type { DesignInfo } from './useDesignMetrics';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { NumberControl } from '../../shared/ui/NumberControl';
import { Fact } from './Fact';

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

/** A fact with its value (or a dash without metrics) and, under it, the θ2 it is reached at. */
function ValueFact({
  label,
  text,
  at,
  testId,
}: {
  label: string;
  text: string | null;
  at?: DesignStop;
  testId: string;
}) {
  return (
    <div className="fact fact-wide">
      <dt>{label}</dt>
      <dd className="mono" data-testid={testId}>
        {text ?? '—'}
      </dd>
      {at ? <GoTo what={label} at={at} testId={`${testId}-at`} onGo={null} /> : null}
    </div>
  );
}

/** The design facts: μ extremes, dead centres, swing, time ratio and input limits, with go-to buttons where allowed. */
function DesignFactList({ facts, onGo }: { facts: DesignFacts | null; onGo: ((theta2Deg: number) => void) | null }) {
  const t = useMessages();
  const names = { extended: t.deadCentreExtended, folded: t.deadCentreFolded };
  return (
    <dl className="facts">
      <ValueFact label={t.designMuMin} text={facts?.muMinText ?? null} at={facts?.muMinAt} testId="design-mu-min" />
      <ValueFact label={t.designMuMax} text={facts?.muMaxText ?? null} at={facts?.muMaxAt} testId="design-mu-max" />
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
        <Fact label={t.swing} mono testId="design-swing">
          {facts.swingText}
        </Fact>
      ) : null}
      {facts?.timeRatioText ? (
        <Fact label={t.timeRatio} mono testId="design-time-ratio">
          {facts.timeRatioText}
        </Fact>
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
  );
}

/** The usable μ band's two fields; a band whose ends are out of order is refused with a message. */
function MuBandFields({ loDeg, hiDeg, dispatch }: { loDeg: number; hiDeg: number; dispatch: Dispatch<Action> }) {
  const t = useMessages();
  const [bandError, setBandError] = useState(false);
  const setBand = (lo: number, hi: number) => {
    setBandError(!(lo < hi));
    if (lo < hi) dispatch({ type: 'setMuBand', loDeg: lo, hiDeg: hi });
  };
  return (
    <div className="band-fields" role="group" aria-label={t.muBand}>
      <h3 className="subhead">{t.muBand}</h3>
      <NumberControl
        field="muBandLo"
        value={loDeg}
        min={0}
        max={180}
        step={1}
        unit="°"
        onCommit={(v) => setBand(v, hiDeg)}
      />
      <NumberControl
        field="muBandHi"
        value={hiDeg}
        min={0}
        max={180}
        step={1}
        unit="°"
        onCommit={(v) => setBand(loDeg, v)}
      />
      {bandError ? (
        <p className="note note-error" role="alert">
          {t.muBandOrder}
        </p>
      ) : null}
    </div>
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
  // "Go to" stops Play first, so the chosen θ2 is the one that stays on screen.
  const onGo = theta2Locked
    ? null
    : (theta2Deg: number) => {
        dispatch({ type: 'setPlaying', playing: false });
        dispatch({ type: 'setTheta2', deg: theta2Deg });
      };
  return (
    <div className="design analysis">
      <DesignFactList facts={facts} onGo={onGo} />
      {facts && !facts.deadCentres && facts.limits.length === 0 ? <p className="note">{t.noDeadCentres}</p> : null}
      {design && !facts ? (
        <p className="note" data-testid="design-cannot-assemble">
          {t.cannotAssembleAny}
        </p>
      ) : null}
      {!compact ? <MuBandFields loDeg={muBandLoDeg} hiDeg={muBandHiDeg} dispatch={dispatch} /> : null}
    </div>
  );
}

/**
 * The design metrics panel: transmission-angle extremes with their θ2, the dead centres (with go-to buttons),
 * the rocker's swing and the time ratio of a crank-rocker, a rocking input's limits, and the usable μ band.
 */
export const DesignPanel = memo(DesignPanelImpl);
