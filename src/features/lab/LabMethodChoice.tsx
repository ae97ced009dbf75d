import type { Dispatch } from 'react';
import type { SweepMethod } from '../../solver/types';
import type { Action } from '../../shared/state/appState';
import { LAB_TOLERANCES } from '../../study/options';
import { SWEEP_METHODS } from '../../solver/methods';
import { useMessages } from '../../shared/i18n/MessagesContext';
import type { LabMessages } from './labMessages';
import { formatTol } from './workPrecisionChart';

/** Props of LabMethodChoice: the chosen method and tolerance, their dispatch, the lab's strings. */
export interface LabMethodChoiceProps {
  method: SweepMethod;
  tol: number | null;
  lt: LabMessages;
  dispatch: Dispatch<Action>;
}

/** The method and tolerance that drive the main view (the closed forms have no tolerance to choose). */
export function LabMethodChoice({ method, tol, lt, dispatch }: LabMethodChoiceProps) {
  const t = useMessages();
  return (
    <div className="lab-choose">
      <label className="field-inline">
        <span>{lt.labMethod}</span>
        <select
          className="select"
          aria-label={lt.labMethod}
          value={method}
          onChange={(e) => dispatch({ type: 'setMethod', method: e.target.value as SweepMethod, tol })}
        >
          {SWEEP_METHODS.map((m) => (
            <option key={m} value={m}>
              {t.methodNames[m]}
            </option>
          ))}
        </select>
      </label>
      <label className="field-inline">
        <span>{lt.labTolerance}</span>
        <select
          className="select"
          aria-label={lt.labTolerance}
          value={tol === null ? 'default' : String(tol)}
          disabled={method === 'closed-form' || method === 'closed-form-polish'}
          onChange={(e) =>
            dispatch({ type: 'setMethod', method, tol: e.target.value === 'default' ? null : Number(e.target.value) })
          }
        >
          <option value="default">{lt.labToleranceDefault}</option>
          {LAB_TOLERANCES.map((x) => (
            <option key={x} value={String(x)}>
              {formatTol(x)}
            </option>
          ))}
        </select>
      </label>
      <p className="note note-muted">{lt.labChooseNote}</p>
    </div>
  );
}
