import { degToRad, radToDeg } from '../../solver';
import type { SpatialState } from '../../shared/state/appState';
import type { SpatialModel, SpatialPreset } from '../../spatial';
import { SPATIAL_PRESETS } from '../../spatial';

/** The spatial numerics' model of the page's state (degrees to radians here, the page's one conversion). */
export function modelOf(s: SpatialState): SpatialModel {
  if (s.kind === 'rssr') {
    return {
      kind: 'rssr',
      linkage: { r2: s.r2, r3: s.r3, r4: s.r4, a: s.a, beta: degToRad(s.betaDeg), h2: s.h2, h4: s.h4 },
    };
  }
  const base = { a1: degToRad(s.a1Deg), a2: degToRad(s.a2Deg), a3: degToRad(s.a3Deg), a4: degToRad(s.a4Deg) };
  // pd = 0 is "no coupler point" (the CSV then has no P columns).
  return {
    kind: 'spherical',
    linkage: s.pDistDeg > 0 ? { ...base, pDist: degToRad(s.pDistDeg), pAngle: degToRad(s.pAngleDeg) } : base,
  };
}

/** Degrees on the URL's grid (9 decimals), so a preset's state round-trips through a link unchanged. */
const deg = (rad: number) => Number(radToDeg(rad).toFixed(9));

/** The state a preset sets: its kind and values (degrees), θ2 and the branch kept. */
export function presetPatch(p: SpatialPreset): Partial<SpatialState> {
  if (p.model.kind === 'rssr') {
    const l = p.model.linkage;
    return { kind: 'rssr', r2: l.r2, r3: l.r3, r4: l.r4, a: l.a, betaDeg: deg(l.beta), h2: l.h2, h4: l.h4 };
  }
  const l = p.model.linkage;
  return {
    kind: 'sph',
    a1Deg: deg(l.a1),
    a2Deg: deg(l.a2),
    a3Deg: deg(l.a3),
    a4Deg: deg(l.a4),
    pDistDeg: l.pDist === undefined ? 0 : deg(l.pDist),
    pAngleDeg: l.pAngle === undefined ? 0 : deg(l.pAngle),
  };
}

/** The preset the state is, or null when a value differs from every preset's. */
export function presetOf(s: SpatialState): SpatialPreset['id'] | null {
  for (const p of SPATIAL_PRESETS) {
    const patch = presetPatch(p);
    if ((Object.keys(patch) as (keyof SpatialState)[]).every((k) => patch[k] === s[k])) return p.id;
  }
  return null;
}

/** The presets in the list's order. */
export const PRESET_IDS = SPATIAL_PRESETS.map((p) => p.id);

/** The preset of an id. */
export function presetById(id: SpatialPreset['id']): SpatialPreset {
  return SPATIAL_PRESETS.find((p) => p.id === id)!;
}
