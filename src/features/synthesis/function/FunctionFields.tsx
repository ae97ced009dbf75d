import type { Dispatch } from 'react';
import type { Action } from '../../../shared/state/appState';
import type { RangeProblem, SynFunctionState } from '../../../shared/state/slices/synFunctionSlice';
import { MAX_FN_POINTS, RANGE_DEG_MAX, rangeLimit, rangeProblem } from '../../../shared/state/slices/synFunctionSlice';
import { formatNumber } from '../../../shared/format';
import { NumberField } from '../../../shared/ui/NumberField';
import type { FunctionMessages } from './functionMessages';

/** Props of FunctionFields: the mode's slice, dispatch and the texts. */
export interface FunctionFieldsProps {
  s: SynFunctionState;
  dispatch: Dispatch<Action>;
  fm: FunctionMessages;
}

type RangeKey = 'xRange' | 'theta2RangeDeg' | 'theta4RangeDeg';

/** The x, θ2 and θ4 ranges (each end a field, checked against the other end) and the number of precision points. */
export function FunctionFields({ s, dispatch, fm }: FunctionFieldsProps) {
  const why = (p: RangeProblem, kind: 'x' | 'angle') =>
    p === 'ends' || p === 'finite'
      ? fm.rangeWhy.ends
      : p === 'within'
        ? fm.rangeWhy.within(formatNumber(rangeLimit(kind)))
        : fm.rangeWhy.span(String(RANGE_DEG_MAX));
  const rows: [RangeKey, 'x' | 'angle', string, string, string | undefined][] = [
    ['xRange', 'x', fm.xFrom, fm.xTo, undefined],
    ['theta2RangeDeg', 'angle', fm.theta2From, fm.theta2To, '°'],
    ['theta4RangeDeg', 'angle', fm.theta4From, fm.theta4To, '°'],
  ];
  return (
    <div className="synmode-fn-fields">
      {rows.map(([key, kind, fromLabel, toLabel, unit]) => (
        <div key={key} className="synmode-field-row">
          {([0, 1] as const).map((end) => {
            const label = end === 0 ? fromLabel : toLabel;
            const range = s[key];
            return (
              <NumberField
                live
                key={end}
                label={label}
                value={range[end]}
                unit={unit}
                check={(v) => {
                  const next: [number, number] = end === 0 ? [v, range[1]] : [range[0], v];
                  const p = rangeProblem(next, kind);
                  return p ? why(p, kind) : null;
                }}
                errorText={(text, kept, w) => fm.fieldError(label, text, kept, w)}
                onCommit={(v) =>
                  dispatch({
                    type: 'setSynFunction',
                    patch: { [key]: end === 0 ? [v, range[1]] : [range[0], v] },
                  })
                }
              />
            );
          })}
        </div>
      ))}
      <div className="synmode-field-row">
        <NumberField
          live
          label={fm.precisionPoints}
          value={s.precisionPoints}
          check={(v) => (Number.isInteger(v) && v >= 3 && v <= MAX_FN_POINTS ? null : fm.pointsWhy(MAX_FN_POINTS))}
          errorText={(text, kept, w) => fm.fieldError(fm.precisionPoints, text, kept, w)}
          onCommit={(v) => dispatch({ type: 'setSynFunction', patch: { precisionPoints: v } })}
        />
      </div>
      <p className="note">{fm.precisionNote}</p>
    </div>
  );
}
