import { wrapDeg180 } from '../../../solver/angles';
import type { Branch, Linkage } from '../../../solver/types';
import { enumCodec, numberCodec } from '../../url/urlCodec';
import type { UrlKey } from '../../url/urlKey';
import { nestedLens, optionalKey, sameText, sliceLens, urlKey } from '../../url/urlKey';
import type { Action } from '../appState';
import type { Slice } from '../slice';
import { URL_ANGLE_DECIMALS } from '../../url/urlPrecision';

/** The app's length unit: lengths are numbers in it; the forces convert them to metres (METRES_PER_UNIT). */
export type LengthUnit = 'mm' | 'cm' | 'm' | 'in';

/** The length units in the order the unit control lists them. */
export const LENGTH_UNITS: readonly LengthUnit[] = ['mm', 'cm', 'm', 'in'];

/** Metres in one length unit (the inch is 25.4 mm exactly). */
export const METRES_PER_UNIT: Readonly<Record<LengthUnit, number>> = { mm: 1e-3, cm: 1e-2, m: 1, in: 0.0254 };

/**
 * A length in `from` as the same length in `to` (6 m is 6000 mm). A result within a few units in the last place of
 * a 12-digit decimal is that decimal, so the unit's factor leaves no float noise (6 m to inches and back is 6).
 */
export function convertLength(x: number, from: LengthUnit, to: LengthUnit): number {
  if (from === to) return x;
  const y = (x * METRES_PER_UNIT[from]) / METRES_PER_UNIT[to];
  const short = Number(y.toPrecision(12));
  return Math.abs(short - y) <= 4 * Number.EPSILON * Math.abs(y) ? short : y;
}

/** Coupler point P on the coupler plane: distance from the crank pin A (length unit) and angle from AB (degrees, CCW). */
export interface CouplerPoint {
  distance: number;
  angleDeg: number;
}

/** Where the linkage sits in the plane: O2 (length unit) and the direction of the ground line O2→O4 (degrees, CCW). */
export interface Placement {
  x: number;
  y: number;
  angleDeg: number;
}

/** The design slice: what the linkage is (lengths in one user unit, the assembly branch, the coupler point) and where. */
export interface DesignState {
  linkage: Linkage;
  branch: Branch;
  coupler: CouplerPoint;
  /** A rigid placement of the whole linkage (from synthesis); default O2 at the origin, ground along +x. */
  placement: Placement;
  /** The unit every length is in (URL lu); default m. */
  lengthUnit: LengthUnit;
}

/** Actions only the design slice handles. */
export type DesignAction =
  | { type: 'setLength'; field: keyof Linkage; value: number }
  | { type: 'setLinkage'; linkage: Linkage }
  | { type: 'setBranch'; branch: Branch }
  | { type: 'toggleBranch' }
  | { type: 'setCoupler'; coupler: Partial<CouplerPoint> }
  | { type: 'setPlacement'; placement: Placement }
  /** The same linkage in another unit: every length is converted (6 m becomes 6000 mm), so the forces stay. */
  | { type: 'setLengthUnit'; from: LengthUnit; to: LengthUnit };

/** O2 at the origin, the ground line along +x. */
export const DEFAULT_PLACEMENT: Placement = { x: 0, y: 0, angleDeg: 0 };

/** The report's linkage: r1 = 6, r2 = 2, r3 = 5, r4 = 5 m, open branch, P at 2.5 and 30 deg. */
export const DEFAULT_DESIGN: DesignState = {
  linkage: { r1: 6, r2: 2, r3: 5, r4: 5 },
  branch: 'open',
  coupler: { distance: 2.5, angleDeg: 30 },
  placement: DEFAULT_PLACEMENT,
  lengthUnit: 'm',
};

/** The design slice's reducer: pure, returns the same object when nothing changes. */
export function designReducer(s: DesignState, action: Action): DesignState {
  switch (action.type) {
    case 'setLength':
      if (s.linkage[action.field] === action.value) return s;
      return { ...s, linkage: { ...s.linkage, [action.field]: action.value } };
    case 'setLinkage':
      return { ...s, linkage: { ...action.linkage } };
    case 'setBranch':
      return action.branch === s.branch ? s : { ...s, branch: action.branch };
    case 'toggleBranch':
      return { ...s, branch: s.branch === 'open' ? 'crossed' : 'open' };
    case 'setCoupler':
      return { ...s, coupler: { ...s.coupler, ...action.coupler } };
    case 'setPlacement': {
      const p = action.placement;
      const q = s.placement;
      return p.x === q.x && p.y === q.y && p.angleDeg === q.angleDeg ? s : { ...s, placement: { ...p } };
    }
    case 'setLengthUnit': {
      if (action.to === s.lengthUnit && action.from === action.to) return s;
      const len = (x: number) => convertLength(x, action.from, action.to);
      const { r1, r2, r3, r4 } = s.linkage;
      return {
        ...s,
        linkage: { r1: len(r1), r2: len(r2), r3: len(r3), r4: len(r4) },
        coupler: { ...s.coupler, distance: len(s.coupler.distance) },
        placement: { ...s.placement, x: len(s.placement.x), y: len(s.placement.y) },
        lengthUnit: action.to,
      };
    }
    case 'animate':
      return action.branch === s.branch ? s : { ...s, branch: action.branch };
    case 'applyPreset':
      // A preset is a linkage of its own: it goes back to the default placement.
      return {
        ...s,
        linkage: { ...action.linkage },
        branch: action.branch,
        coupler: { ...action.coupler },
        placement: DEFAULT_PLACEMENT,
      };
    default:
      return s;
  }
}

const length = nestedLens('design', 'linkage');
const coupler = nestedLens('design', 'coupler');
const angle180 = numberCodec('couplerAngle', { decimals: URL_ANGLE_DECIMALS, normalize: wrapDeg180 });
const placement = nestedLens('design', 'placement');
/** O2's coordinates in the URL: any finite position up to a billion length units (exact text). */
const position = numberCodec({ min: -1e9, max: 1e9 });
const groundAngle = numberCodec({ min: -360, max: 360 }, { decimals: URL_ANGLE_DECIMALS, normalize: wrapDeg180 });

/**
 * The design's URL keys: r1 to r4, br, pd, pa, the placement ox, oy, og when it is not the default, and the length
 * unit lu when it is not m (a link sets the unit without converting: its lengths are already in it).
 */
export const DESIGN_URL_KEYS: readonly UrlKey<unknown>[] = [
  urlKey('r1', numberCodec('r1'), length('r1')),
  urlKey('r2', numberCodec('r2'), length('r2')),
  urlKey('r3', numberCodec('r3'), length('r3')),
  urlKey('r4', numberCodec('r4'), length('r4')),
  urlKey('br', enumCodec(sameText(['open', 'crossed'] as const)), sliceLens('design')('branch')),
  urlKey('pd', numberCodec('couplerDistance'), coupler('distance')),
  urlKey('pa', angle180, coupler('angleDeg')),
  optionalKey('ox', position, placement('x'), DEFAULT_PLACEMENT.x),
  optionalKey('oy', position, placement('y'), DEFAULT_PLACEMENT.y),
  optionalKey('og', groundAngle, placement('angleDeg'), DEFAULT_PLACEMENT.angleDeg),
  optionalKey('lu', enumCodec(sameText(LENGTH_UNITS)), sliceLens('design')('lengthUnit'), DEFAULT_DESIGN.lengthUnit),
];

/** The design slice's registration in SLICES (appState.ts). */
export const DESIGN_SLICE: Slice<DesignState, DesignAction> = {
  summary: 'what the linkage is: lengths and their unit, branch, coupler point, placement',
  defaults: DEFAULT_DESIGN,
  reducer: designReducer,
  urlKeys: DESIGN_URL_KEYS,
};
