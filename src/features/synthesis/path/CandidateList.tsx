import type { Dispatch } from 'react';
import type { Point } from '../../../solver/kinematics';
import type { PathSolution } from '../../../synthesis/types';
import type { Messages } from '../../../shared/i18n/messages';
import { formatDeg, formatNumber, formatSci, roundingNoiseToZero } from '../../../shared/format';
import type { Action } from '../../../shared/state/appState';
import type { SynthesisMessages } from '../synthesisMessages';
import type { CandidateFacts } from './candidateFacts';
import { CandidateThumb } from './CandidateThumb';
import { targetsExtent } from './pathTaskOf';

/** Props of CandidateList: the answers with their facts, the targets, which is chosen, and the dispatch. */
export interface CandidateListProps {
  solutions: readonly PathSolution[];
  facts: readonly CandidateFacts[];
  /** For each candidate, the rank of one above it that it is a Roberts cognate of, or null. */
  cognateOf: readonly (number | null)[];
  targets: readonly Point[];
  chosen: number;
  /** The answers are for another task than the page's (an edit since the run): shown dimmed, marked out of date. */
  stale: boolean;
  dispatch: Dispatch<Action>;
  st: SynthesisMessages;
  t: Messages;
}

/** The type in words: "Crank-rocker (Grashof)". */
export function typeText(f: CandidateFacts, t: Messages, st: SynthesisMessages): string {
  const change = f.defects.some((d) => d.kind === 'change-point');
  return `${t.types[f.type]} (${change ? st.changePoint : f.grashof ? st.grashof : st.nonGrashof})`;
}

/**
 * A distance beside the targets' size (length unit) in exponent form, 0 when it is rounding noise (at most
 * ROUNDING_NOISE of the size: an exact fit's 5e−15 beside 2 reads 0).
 */
export function distanceText(d: number, size: number): string {
  return formatSci(roundingNoiseToZero(d, size), 3);
}

/** Σd² beside the targets' size (length unit): 0 when its root is rounding noise of the size (see distanceText). */
export function errorSumText(sum: number, size: number): string {
  return roundingNoiseToZero(Math.sqrt(sum), size) === 0 ? '0' : formatSci(sum, 3);
}

/** The defects in words, or "none". */
export function defectsText(f: CandidateFacts, st: SynthesisMessages): string {
  if (f.defects.length === 0) return st.noDefects;
  return f.defects
    .map((d) =>
      st.defectText[d.kind](
        d.kind === 'low-transmission' || d.kind === 'toggle' ? `${formatDeg(d.value, 1)}°` : formatNumber(d.value, 3),
      ),
    )
    .join('; ');
}

/**
 * The candidates, best first (marked out of date when the task changed since the run): each a button (pressed when chosen) with its thumbnail, Σd², max distance, type,
 * smallest transmission angle, defects in words, and a mark when it is a cognate of one above.
 */
export function CandidateList({
  solutions,
  facts,
  cognateOf,
  targets,
  chosen,
  stale,
  dispatch,
  st,
  t,
}: CandidateListProps) {
  if (solutions.length === 0) return null;
  const size = targetsExtent(targets).size;
  return (
    <section className={`card syn-card${stale ? ' is-stale' : ''}`} aria-labelledby="syn-results-title">
      <h3 id="syn-results-title" className="syn-card-title">
        {st.resultsTitle}
      </h3>
      {stale ? (
        <p className="syn-stale-note" data-testid="stale-note">
          {st.staleResults}
        </p>
      ) : null}
      <ol className="syn-candidates" data-testid="candidates" data-stale={stale}>
        {solutions.map((s, i) => {
          const f = facts[i];
          return (
            <li key={i}>
              <button
                type="button"
                className={`syn-candidate${i === chosen ? ' is-chosen' : ''}`}
                aria-pressed={i === chosen}
                data-error={s.error}
                onClick={() => dispatch({ type: 'chooseCandidate', index: i })}
              >
                <CandidateThumb curve={f.curve} targets={targets} />
                <span className="syn-candidate-text">
                  <strong>{st.candidateName(i + 1)}</strong>
                  <span>
                    {st.errorSum} {errorSumText(s.error, size)} · {st.maxDistance} {distanceText(s.maxDistance, size)}
                  </span>
                  <span>
                    {typeText(f, t, st)} · {st.minTransmission} {formatDeg(f.muMinDeg, 1)}°
                  </span>
                  <span className={f.defects.length > 0 ? 'syn-defects' : undefined}>
                    {st.defects}: {defectsText(f, st)}
                  </span>
                  {cognateOf[i] !== null ? (
                    <span className="syn-cognate-mark">{st.cognateOf(cognateOf[i] ?? 0)}</span>
                  ) : null}
                </span>
              </button>
            </li>
          );
        })}
      </ol>
    </section>
  );
}
