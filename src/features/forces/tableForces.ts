// The solver's modules themselves, not its barrel: the barrel would pull the sweep and NR into the main bundle.
import { degToRad } from '../../solver/angles';
import { sweepForces } from '../../solver/forces';
import type { SweepForces } from '../../solver/forces';
import { STATUS_CODE } from '../../solver/pointStatus';
import type { CycleForces } from '../../shared/csv';
import type { TableResponse } from '../../shared/solution';
import type { ForceInputs, ForceSetup } from './forceModel';
import { forceSetup } from './forceModel';

/** The rows of the n-point table the force columns are computed on: θ2 in degrees, θ3 and θ4 in radians, statuses. */
export type TableRows = Pick<TableResponse, 'theta2Deg' | 'theta3Rad' | 'theta4Rad' | 'statusCodes'>;

/**
 * The forces (SI) at each row of the n-point table, the cycle CSV's force columns: sweepForces on the table's own
 * angles, NaN where a row is not assembled or is a limit position.
 */
export function tableForces(setup: ForceSetup, tbl: TableRows): SweepForces {
  const theta2 = Float64Array.from(tbl.theta2Deg, (d) => degToRad(d));
  const codes = tbl.statusCodes;
  return sweepForces(
    setup.linkage,
    theta2,
    tbl.theta3Rad,
    tbl.theta4Rad,
    (i) => codes[i] === STATUS_CODE.ok,
    setup.input,
    setup.inertia,
    setup.loads,
  );
}

/**
 * What the cycle CSV's export asks for its force columns: null while Forces is off (no columns, nothing solved),
 * else the table's forces for this state's setup.
 */
export function forceColumnsFor(state: ForceInputs): ((tbl: TableRows) => CycleForces) | null {
  if (!state.forces.enabled) return null;
  return (tbl) => tableForces(forceSetup(state), tbl);
}
