import { formatNumber } from '../../../shared/format';
import type { Messages } from '../../../shared/i18n/messages';
import type { PlacedFourBar } from '../../../synthesis/types';
import type { SynthesisMessages } from '../synthesisMessages';
import type { CandidateFacts } from './candidateFacts';
import { defectsText, typeText } from './CandidateList';

/** One linkage the chosen card offers: the candidate itself or one of its cognates, with its facts. */
export interface DesignChoice {
  design: PlacedFourBar;
  facts: CandidateFacts;
}

/** Props of ChosenDesign: the candidate and its cognates, which one is shown, and the actions. */
export interface ChosenDesignProps {
  choices: readonly DesignChoice[];
  shown: number;
  onShow: (index: number) => void;
  /** The design was found for another task than the page's: it is not opened with the new targets. */
  stale: boolean;
  onOpen: () => void;
  onExportCsv: () => void;
  onExportSvg: () => void;
  onExportPng: () => void;
  st: SynthesisMessages;
  t: Messages;
}

/**
 * The chosen design: the candidate and its two Roberts cognates as a radio group (the one chosen is drawn and
 * opened), "Open in simulator" (not for an out-of-date design), and the exports (results CSV, the canvas as SVG and PNG).
 */
export function ChosenDesign({
  choices,
  shown,
  onShow,
  stale,
  onOpen,
  onExportCsv,
  onExportSvg,
  onExportPng,
  st,
  t,
}: ChosenDesignProps) {
  const fmt = (x: number) => formatNumber(x, 4);
  return (
    <section className="card syn-card" aria-labelledby="syn-chosen-title">
      <h3 id="syn-chosen-title" className="syn-card-title">
        {st.chosenTitle}
      </h3>
      <fieldset className="syn-cognates">
        <legend className="syn-field-label">{st.cognatesTitle}</legend>
        <p className="note">{st.cognatesIntro}</p>
        {choices.map((c, i) => {
          const l = c.design.links;
          return (
            <label key={i} className={`syn-cognate${i === shown ? ' is-on' : ''}`}>
              <input type="radio" name="syn-cognate" checked={i === shown} onChange={() => onShow(i)} />
              <span>
                <strong>{i === 0 ? st.cognateOriginal : st.cognateName(i)}</strong>
                <span className="syn-cognate-detail">
                  {st.lengths(fmt(l.r1), fmt(l.r2), fmt(l.r3), fmt(l.r4))} · {typeText(c.facts, t, st)}
                </span>
                <span className="syn-cognate-detail">
                  {st.defects}: {defectsText(c.facts, st)}
                </span>
              </span>
            </label>
          );
        })}
      </fieldset>
      {stale ? <p className="note">{st.staleOpen}</p> : null}
      <div className="syn-buttons">
        <button type="button" className="btn btn-primary" disabled={stale} onClick={onOpen}>
          {st.openInSimulator}
        </button>
        <button type="button" className="btn" onClick={onExportCsv}>
          {st.exportResultsCsv}
        </button>
        <button type="button" className="btn" onClick={onExportSvg}>
          {st.exportSvg}
        </button>
        <button type="button" className="btn" onClick={onExportPng}>
          {st.exportPng}
        </button>
      </div>
    </section>
  );
}
