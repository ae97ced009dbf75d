import { useId, useRef, useState } from 'react';
import type { Dispatch } from 'react';
import type { Point } from '../../../solver/kinematics';
import { downloadText } from '../../../shared/canvas/download';
import type { Action, SynPathState } from '../../../shared/state/appState';
import { NumberField } from '../../../shared/ui/NumberField';
import type { SynthesisMessages } from '../synthesisMessages';
import type { TargetsTextError } from './targetsText';
import { formatTargetsText, parseTargetsText, targetsToCsv } from './targetsText';

/** Props of TargetsCard: the task, the selection and the edits. */
export interface TargetsCardProps {
  s: SynPathState;
  selected: number | null;
  onSelect: (index: number | null) => void;
  /** New targets from a paste, an import or the example: the canvas refits to them. */
  onReplace: (targets: Point[], theta2Deg: number[] | null) => void;
  dispatch: Dispatch<Action>;
  st: SynthesisMessages;
}

/** Eight points of the report linkage's coupler curve (r = 6, 2, 5, 5; P at 2.5, 30°; θ2 every 45°), to 0.01. */
export const EXAMPLE_TARGETS: Point[] = [
  { x: 1.72, y: 2.48 },
  { x: 2.1, y: 3.82 },
  { x: 1.16, y: 4.21 },
  { x: -0.17, y: 3.58 },
  { x: -1.02, y: 2.3 },
  { x: -1.06, y: 1.06 },
  { x: -0.4, y: 0.47 },
  { x: 0.62, y: 0.96 },
];

function errorText(e: TargetsTextError, st: SynthesisMessages): string {
  return e.kind === 'line' ? st.pasteBadLine(e.line, e.text) : st.pasteTooMany(e.max);
}

/** The "Target points" text area: pasted lines replace the targets when they all read; a bad line is named. */
function TargetPaste({ s, onReplace, st }: Pick<TargetsCardProps, 's' | 'onReplace' | 'st'>) {
  const id = useId();
  const [draft, setDraft] = useState<string | null>(null);
  const [error, setError] = useState<string | null>(null);
  const timed = s.timing === 'given' ? s.givenTheta2Deg : null;
  const shown = draft ?? formatTargetsText(s.targets, timed);
  const read = (text: string) => {
    // The app's own CSV (Export CSV) pastes back: its header line is skipped.
    const r = parseTargetsText(text, true);
    if (!r.ok) {
      setError(errorText(r.error, st));
      return;
    }
    setError(null);
    onReplace(r.value.targets, r.value.theta2Deg);
  };
  return (
    <div className="syn-paste">
      <label htmlFor={id} className="syn-field-label">
        {st.pasteLabel}
      </label>
      <textarea
        id={id}
        rows={5}
        spellCheck={false}
        value={shown}
        aria-invalid={error ? true : undefined}
        aria-describedby={`${id}-help`}
        onChange={(e) => {
          setDraft(e.target.value);
          read(e.target.value);
        }}
        onBlur={() => {
          if (!error) setDraft(null);
        }}
      />
      <p id={`${id}-help`} className="note">
        {st.pasteHelp}
      </p>
      {error ? (
        <p className="syn-error" role="alert" data-testid="paste-error">
          {error}
        </p>
      ) : null}
    </div>
  );
}

/** The editable x, y (and θ2) table of the targets, one row per target, with a remove button each. */
function TargetTable({ s, selected, onSelect, dispatch, st }: Omit<TargetsCardProps, 'onReplace'>) {
  const given = s.timing === 'given';
  const setAt = (i: number, p: Partial<Point>) =>
    dispatch({ type: 'setTargets', targets: s.targets.map((t, k) => (k === i ? { ...t, ...p } : t)) });
  const remove = (i: number) => {
    dispatch({ type: 'removeTarget', index: i });
    onSelect(null);
  };
  /** θ2 of target i (NaN: not given), the others kept; a target without one stays without (never a silent 0). */
  const setTheta2 = (i: number, a: number) => {
    const next = s.targets.map((_, k) => s.givenTheta2Deg[k] ?? NaN);
    next[i] = a;
    dispatch({ type: 'setGivenTheta2', theta2Deg: next });
  };
  if (s.targets.length === 0) return null;
  return (
    <table className="syn-table">
      <thead>
        <tr>
          <th scope="col">#</th>
          <th scope="col">{st.tableX}</th>
          <th scope="col">{st.tableY}</th>
          {given ? <th scope="col">{st.tableTheta2}</th> : null}
          <th scope="col">
            <span className="sr-only">{st.clearTargets}</span>
          </th>
        </tr>
      </thead>
      <tbody>
        {s.targets.map((t, i) => (
          <tr key={i} className={selected === i ? 'is-selected' : undefined} onFocus={() => onSelect(i)}>
            <th scope="row">{st.targetName(i + 1)}</th>
            <td>
              <NumberField
                label={`${st.targetName(i + 1)} ${st.tableX}`}
                hideLabel
                value={t.x}
                className="syn-field"
                errorText={st.badNumber}
                onCommit={(x) => setAt(i, { x })}
              />
            </td>
            <td>
              <NumberField
                label={`${st.targetName(i + 1)} ${st.tableY}`}
                hideLabel
                value={t.y}
                className="syn-field"
                errorText={st.badNumber}
                onCommit={(y) => setAt(i, { y })}
              />
            </td>
            {given ? (
              <td>
                <NumberField
                  label={`${st.targetName(i + 1)} ${st.tableTheta2}`}
                  hideLabel
                  value={Number.isFinite(s.givenTheta2Deg[i]) ? s.givenTheta2Deg[i] : null}
                  className="syn-field"
                  errorText={st.badNumber}
                  onCommit={(a) => setTheta2(i, a)}
                  onClear={() => setTheta2(i, NaN)}
                />
              </td>
            ) : null}
            <td>
              <button
                type="button"
                className="syn-remove"
                aria-label={st.removeTarget(i + 1)}
                title={st.removeTarget(i + 1)}
                onClick={() => remove(i)}
              >
                ×
              </button>
            </td>
          </tr>
        ))}
      </tbody>
    </table>
  );
}

/**
 * The targets card: the "Target points" text area, the x/y table, Import CSV, Export CSV, Example and Clear.
 */
export function TargetsCard(props: TargetsCardProps) {
  const { s, onReplace, st } = props;
  const fileRef = useRef<HTMLInputElement>(null);
  const [importError, setImportError] = useState<string | null>(null);
  const importFile = async (file: File) => {
    const r = parseTargetsText(await file.text(), true);
    if (!r.ok) {
      setImportError(st.importFailed(errorText(r.error, st)));
      return;
    }
    setImportError(null);
    onReplace(r.value.targets, r.value.theta2Deg);
  };
  return (
    <section className="card syn-card" aria-labelledby="syn-targets-title">
      <h3 id="syn-targets-title" className="syn-card-title">
        {st.targetsTitle}
      </h3>
      <TargetPaste s={s} onReplace={onReplace} st={st} />
      <TargetTable {...props} />
      <div className="syn-buttons">
        <button type="button" className="btn" onClick={() => fileRef.current?.click()}>
          {st.importCsv}
        </button>
        <input
          ref={fileRef}
          type="file"
          accept=".csv,.txt,text/csv,text/plain"
          className="sr-only"
          tabIndex={-1}
          aria-hidden="true"
          data-testid="targets-file"
          onChange={(e) => {
            const f = e.target.files?.[0];
            if (f) void importFile(f);
            e.target.value = '';
          }}
        />
        <button
          type="button"
          className="btn"
          disabled={s.targets.length === 0}
          onClick={() =>
            downloadText(
              targetsToCsv(s.targets, s.timing === 'given' ? s.givenTheta2Deg : null),
              'targets.csv',
              'text/csv;charset=utf-8',
            )
          }
        >
          {st.exportCsv}
        </button>
        <button type="button" className="btn" onClick={() => onReplace(EXAMPLE_TARGETS, null)}>
          {st.exampleTargets}
        </button>
        <button type="button" className="btn" disabled={s.targets.length === 0} onClick={() => onReplace([], null)}>
          {st.clearTargets}
        </button>
      </div>
      {importError ? (
        <p className="syn-error" role="alert">
          {importError}
        </p>
      ) : null}
    </section>
  );
}
