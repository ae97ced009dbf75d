import type { PoseDeg } from '../../../shared/state/slices/synMotionSlice';
import { COORD_MAX, MAX_POSES, MIN_POSES } from '../../../shared/state/slices/synMotionSlice';
import { formatNumber } from '../../../shared/format';
import { NumberField } from '../../../shared/ui/NumberField';
import type { MotionMessages } from './motionMessages';

/** Props of PoseTable: the poses, the selected one, and what editing, adding and removing do. */
export interface PoseTableProps {
  poses: readonly PoseDeg[];
  selected: number;
  onSelect: (index: number) => void;
  onPose: (index: number, pose: PoseDeg) => void;
  onAdd: () => void;
  onRemove: (index: number) => void;
  mt: MotionMessages;
}

/** The poses typed in: x, y and angle per pose (each field validated, naming the cell), add and remove. */
export function PoseTable({ poses, selected, onSelect, onPose, onAdd, onRemove, mt }: PoseTableProps) {
  const coordCheck = (v: number) =>
    Math.abs(v) <= COORD_MAX ? null : mt.mustBeBetween(formatNumber(-COORD_MAX), formatNumber(COORD_MAX));
  const cells = [
    ['x', mt.columnX],
    ['y', mt.columnY],
    ['angleDeg', mt.columnAngle],
  ] as const;
  return (
    <div className="synmode-pose-table-wrap">
      <table className="synmode-table synmode-pose-table">
        <caption className="sr-only">{mt.tableCaption}</caption>
        <thead>
          <tr>
            <th scope="col">#</th>
            {cells.map(([key, title]) => (
              <th key={key} scope="col">
                {title}
              </th>
            ))}
            <th scope="col">
              <span className="sr-only">{mt.removeColumn}</span>
            </th>
          </tr>
        </thead>
        <tbody>
          {poses.map((pose, i) => (
            <tr key={i} className={i === selected ? 'is-selected' : undefined} onFocus={() => onSelect(i)}>
              <th scope="row">{i + 1}</th>
              {cells.map(([key, title]) => (
                <td key={key}>
                  <NumberField
                    live
                    label={`${mt.poseName(i + 1)} ${title}`}
                    hideLabel
                    value={pose[key]}
                    decimals={key === 'angleDeg' ? 2 : 6}
                    check={key === 'angleDeg' ? undefined : coordCheck}
                    errorText={(text, kept, why) => mt.cellError(`${mt.poseName(i + 1)} ${title}`, text, kept, why)}
                    onCommit={(value) => onPose(i, { ...pose, [key]: value })}
                  />
                </td>
              ))}
              <td>
                <button
                  type="button"
                  className="btn btn-small"
                  aria-label={mt.removePose(i + 1)}
                  title={mt.removePose(i + 1)}
                  disabled={poses.length <= MIN_POSES}
                  onClick={() => onRemove(i)}
                >
                  ×
                </button>
              </td>
            </tr>
          ))}
        </tbody>
      </table>
      <button type="button" className="btn btn-small" disabled={poses.length >= MAX_POSES} onClick={onAdd}>
        {mt.addPose}
      </button>
    </div>
  );
}
