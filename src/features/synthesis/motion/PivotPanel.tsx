import type { Point } from '../../../solver';
import type { PivotChoice } from '../../../shared/state/slices/synMotionSlice';
import { COORD_MAX } from '../../../shared/state/slices/synMotionSlice';
import { Segmented } from '../../../shared/ui/Segmented';
import { formatNumber } from '../../../shared/format';
import { NumberField } from '../../../shared/ui/NumberField';
import type { MotionMessages } from './motionMessages';

/** Props of PivotPanel: the choice, the placed pivots, and what changing them does. */
export interface PivotPanelProps {
  choice: PivotChoice;
  pivots: readonly [Point, Point];
  onChoice: (choice: PivotChoice) => void;
  onPivot: (index: 0 | 1, point: Point) => void;
  mt: MotionMessages;
}

/** Three poses: moving or fixed pivots, typed as x and y (they are dragged on the canvas too). */
export function PivotPanel({ choice, pivots, onChoice, onPivot, mt }: PivotPanelProps) {
  const names = choice === 'moving' ? (['A', 'B'] as const) : (['O2', 'O4'] as const);
  const check = (v: number) =>
    Math.abs(v) <= COORD_MAX ? null : mt.mustBeBetween(formatNumber(-COORD_MAX), formatNumber(COORD_MAX));
  return (
    <div className="synmode-pivots">
      <Segmented
        legend={mt.pivotLegend}
        value={choice}
        options={[
          { value: 'moving', label: mt.pivotMoving },
          { value: 'fixed', label: mt.pivotFixed },
        ]}
        onChange={onChoice}
      />
      <p className="note">{mt.pivotTable(choice)}</p>
      <div className="synmode-pivot-grid">
        {([0, 1] as const).map((k) =>
          (['x', 'y'] as const).map((axis) => (
            <NumberField
              live
              key={`${k}${axis}`}
              label={`${names[k]} ${axis}`}
              value={pivots[k][axis]}
              decimals={6}
              check={check}
              errorText={(text, kept, why) => mt.cellError(`${mt.pivotName[names[k]]} ${axis}`, text, kept, why)}
              onCommit={(value) => onPivot(k, { ...pivots[k], [axis]: value })}
            />
          )),
        )}
      </div>
      <p className="note">{mt.constructionNote(choice)}</p>
    </div>
  );
}
