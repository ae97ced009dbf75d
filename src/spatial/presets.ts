import { degToRad } from '../solver';
import type { SpatialModel } from './types';

/** A named starting design for the spatial page (angles in radians, as the numerics take them). */
export interface SpatialPreset {
  id: 'sph-crank-rocker' | 'sph-drag-link' | 'sph-universal-joint' | 'rssr-skew' | 'rssr-planar';
  model: SpatialModel;
}

/**
 * The presets issue 32 asks for: a spherical crank-rocker (with a coupler point), a spherical drag link, a universal
 * joint as a spherical four-bar (crank, coupler and rocker arcs of 90 degrees, shafts 30 degrees apart), an RSSR skew
 * drive (output axis tilted 60 degrees, offset pins) and an RSSR that is the report's planar 6-2-5-5 crank-rocker.
 */
export const SPATIAL_PRESETS: readonly SpatialPreset[] = [
  {
    id: 'sph-crank-rocker',
    model: {
      kind: 'spherical',
      linkage: {
        a1: degToRad(60),
        a2: degToRad(20),
        a3: degToRad(55),
        a4: degToRad(45),
        pDist: degToRad(25),
        pAngle: degToRad(40),
      },
    },
  },
  {
    id: 'sph-drag-link',
    model: { kind: 'spherical', linkage: { a1: degToRad(20), a2: degToRad(45), a3: degToRad(60), a4: degToRad(50) } },
  },
  {
    id: 'sph-universal-joint',
    model: { kind: 'spherical', linkage: { a1: degToRad(30), a2: degToRad(90), a3: degToRad(90), a4: degToRad(90) } },
  },
  {
    id: 'rssr-skew',
    model: { kind: 'rssr', linkage: { r2: 1, r3: 4, r4: 2, a: 3, beta: degToRad(60), h2: 0.5, h4: 1 } },
  },
  {
    id: 'rssr-planar',
    model: { kind: 'rssr', linkage: { r2: 2, r3: 5, r4: 5, a: 6, beta: 0, h2: 0, h4: 0 } },
  },
];
