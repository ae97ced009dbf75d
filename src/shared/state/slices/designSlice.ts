import { wrapDeg180 } from '../../../solver/angles';
import type { Branch, Linkage } from '../../../solver/types';
import { enumCodec, numberCodec } from '../../url/urlCodec';
import type { UrlKey } from '../../url/urlKey';
import { nestedLens, optionalKey, sameText, sliceLens, urlKey } from '../../url/urlKey';
import type { Action } from '../appState';
import type { Slice } from '../slice';
import { URL_ANGLE_DECIMALS } from '../../url/urlPrecision';

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
}

/** Actions only the design slice handles. */
export type DesignAction =
  | { type: 'setLength'; field: keyof Linkage; value: number }
  | { type: 'setLinkage'; linkage: Linkage }
  | { type: 'setBranch'; branch: Branch }
  | { type: 'toggleBranch' }
  | { type: 'setCoupler'; coupler: Partial<CouplerPoint> }
  | { type: 'setPlacement'; placement: Placement };

/** O2 at the origin, the ground line along +x. */
export const DEFAULT_PLACEMENT: Placement = { x: 0, y: 0, angleDeg: 0 };

/** The report's linkage: r1 = 6, r2 = 2, r3 = 5, r4 = 5, open branch, P at 2.5 and 30 deg. */
export const DEFAULT_DESIGN: DesignState = {
  linkage: { r1: 6, r2: 2, r3: 5, r4: 5 },
  branch: 'open',
  coupler: { distance: 2.5, angleDeg: 30 },
  placement: DEFAULT_PLACEMENT,
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
    case 'animate':
      return action.branch === s.branch ? s : { ...s, branch: action.branch };
    case 'applyPreset':
      // A preset is a linkage of its own: it goes back to the default placement.
      return {
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

/** The design's URL keys: r1 to r4, br, pd, pa, and the placement ox, oy, og when it is not the default. */
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
];

/** The design slice's registration in SLICES (appState.ts). */
export const DESIGN_SLICE: Slice<DesignState, DesignAction> = {
  summary: 'what the linkage is: lengths, branch, coupler point, placement',
  defaults: DEFAULT_DESIGN,
  reducer: designReducer,
  urlKeys: DESIGN_URL_KEYS,
};
