import type { MechanismSpec } from '../../mechanism';
import { formatNumber } from '../../shared/format';
import type { MechPose } from './mechPose';

/** Props of MechPositions: the linkage, its pose at the input, and the table's accessible name. */
export interface MechPositionsProps {
  spec: MechanismSpec;
  pose: MechPose;
  label: string;
}

/** Every joint's and tracer's x and y at the input (6 significant digits), in spec order: the embed's numbers. */
export function MechPositions({ spec, pose, label }: MechPositionsProps) {
  const rows = [
    ...spec.joints.map((j) => [j.id, pose.joints[j.id]] as const),
    ...(spec.points ?? []).map((p) => [p.id, pose.points[p.id]] as const),
  ];
  return (
    <table className="mech-positions" aria-label={label}>
      <thead>
        <tr>
          <th scope="col">
            <span className="sr-only">{label}</span>
          </th>
          <th scope="col">x</th>
          <th scope="col">y</th>
        </tr>
      </thead>
      <tbody>
        {rows.map(([id, at]) => (
          <tr key={id}>
            <th scope="row">{id}</th>
            <td className="num" data-testid={`mech-pos-${id}-x`}>
              {at ? formatNumber(at.x, 6) : '—'}
            </td>
            <td className="num" data-testid={`mech-pos-${id}-y`}>
              {at ? formatNumber(at.y, 6) : '—'}
            </td>
          </tr>
        ))}
      </tbody>
    </table>
  );
}
