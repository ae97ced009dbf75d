import type { Dispatch } from 'react';
import type { SweepMethod } from '../../solver/types';
import type { Action } from '../../shared/state/appState';
import { LAB_TOLERANCES } from '../../study/options';
import { SWEEP_METHODS } from '../../solver/methods';
import { useMessages } from '../../shared/i18n/MessagesContext';
import type { LabMessages } from './labMessages';
import { shownTol } from './workPrecisionChart';
import { SelectMenu } from '../../shared/ui/SelectMenu';

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
        <SelectMenu<SweepMethod>
          className="select"
          label={lt.labMethod}
          value={method}
          options={SWEEP_METHODS.map((m) => ({ value: m, label: t.methodNames[m] }))}
          onChange={(m) => dispatch({ type: 'setMethod', method: m, tol })}
        />
      </label>
      <label className="field-inline">
        <span>{lt.labTolerance}</span>
        <SelectMenu
          className="select"
          label={lt.labTolerance}
          value={tol === null ? 'default' : String(tol)}
          disabled={method === 'closed-form' || method === 'closed-form-polish'}
          options={[
            { value: 'default', label: lt.labToleranceDefault },
            ...LAB_TOLERANCES.map((x) => ({ value: String(x), label: shownTol(x) })),
          ]}
          onChange={(v) => dispatch({ type: 'setMethod', method, tol: v === 'default' ? null : Number(v) })}
        />
      </label>
      <p className="note note-muted">{lt.labChooseNote}</p>
    </div>
  );
}
