import { describe, expect, it } from 'vitest';
import { planFixedLayer, sameFixedView } from '../../../src/features/spatial/fixedLayerPlan';
import type { FixedLayerState, FixedLayerView } from '../../../src/features/spatial/fixedLayerPlan';

// A camera as three keeps it: its world matrix (a view 5 units out along -y, looking at the origin) and a perspective
// projection (32° field, aspect 1.25, near 0.01, far 100), both column-major.
const WORLD = [1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, -5, 0, 1];
const PROJECTION = [2.8, 0, 0, 0, 0, 3.5, 0, 0, 0, 0, -1.0002, -1, 0, 0, -0.020002, 0];
const VIEW: FixedLayerView = { camera: [...WORLD, ...PROJECTION], widthPx: 293, heightPx: 240, build: 1 };

/** The view with one camera number changed (index i of the 32) by d. */
const turned = (i: number, d = 1e-9): FixedLayerView => ({
  ...VIEW,
  camera: VIEW.camera.map((x, k) => (k === i ? x + d : x)),
});

/** Play's frames with the camera still: moving, the last frame's view the same as this one's. */
const still = (over: Partial<FixedLayerState> = {}): FixedLayerState => ({
  enabled: true,
  moving: true,
  cached: null,
  previous: VIEW,
  now: VIEW,
  ...over,
});

describe('sameFixedView', () => {
  it('holds for an equal view and fails for none', () => {
    expect(sameFixedView({ ...VIEW, camera: [...VIEW.camera] }, VIEW)).toBe(true);
    expect(sameFixedView(null, VIEW)).toBe(false);
  });
  it('fails for any camera number changed, even by a rounding: an orbit, zoom, pan, projection or aspect', () => {
    for (let i = 0; i < 32; i++) expect(sameFixedView(turned(i), VIEW), `camera[${i}]`).toBe(false);
  });
  it('fails for another drawing buffer (a resize, another pixel ratio) or another build of the fixed parts', () => {
    expect(sameFixedView({ ...VIEW, widthPx: 294 }, VIEW)).toBe(false);
    expect(sameFixedView({ ...VIEW, heightPx: 480 }, VIEW)).toBe(false);
    expect(sameFixedView({ ...VIEW, build: 2 }, VIEW)).toBe(false);
  });
});

describe('planFixedLayer', () => {
  it('draws Play with the camera still on the layer: built on the second moving frame, then used', () => {
    expect(planFixedLayer(still())).toBe('build');
    expect(planFixedLayer(still({ cached: VIEW }))).toBe('cached');
    // The layer serves even when the last frame was drawn otherwise (a PNG, a resize back to the same size).
    expect(planFixedLayer(still({ cached: VIEW, previous: null }))).toBe('cached');
  });
  it('draws in full at rest, whatever the layer: the view at rest looks as it always did', () => {
    expect(planFixedLayer(still({ moving: false }))).toBe('full');
    expect(planFixedLayer(still({ moving: false, cached: VIEW }))).toBe('full');
  });
  it('draws in full where the look does not cache (the full look) or the layer failed', () => {
    expect(planFixedLayer(still({ enabled: false }))).toBe('full');
    expect(planFixedLayer(still({ enabled: false, cached: VIEW }))).toBe('full');
  });
  it('draws an orbit in full: the view changes every frame, a layer for it would not be used again', () => {
    expect(planFixedLayer(still({ previous: turned(12, 0.05), now: VIEW }))).toBe('full');
    expect(planFixedLayer(still({ previous: turned(12, 0.05), now: VIEW, cached: turned(12, 0.05) }))).toBe('full');
    // Play's first frame at the moving resolution: the frame before it (at rest) had another buffer.
    expect(planFixedLayer(still({ previous: { ...VIEW, widthPx: 586, heightPx: 480 } }))).toBe('full');
  });
  it('does not use a stale layer: after a camera move, a resize or a new linkage (the fixed parts rebuilt)', () => {
    expect(planFixedLayer(still({ cached: turned(0) }))).toBe('build');
    expect(planFixedLayer(still({ cached: { ...VIEW, widthPx: 292 } }))).toBe('build');
    const rebuilt = { ...VIEW, build: 2 };
    expect(planFixedLayer(still({ cached: VIEW, previous: VIEW, now: rebuilt }))).toBe('full');
    expect(planFixedLayer(still({ cached: VIEW, previous: rebuilt, now: rebuilt }))).toBe('build');
  });
  it('throws on a view that is not one: the field and the value named', () => {
    expect(() => planFixedLayer(still({ now: { ...VIEW, camera: WORLD } }))).toThrow(/now.camera.*32.*16/);
    expect(() => planFixedLayer(still({ now: turned(3, NaN) }))).toThrow(/now.camera must be finite, got NaN/);
    expect(() => planFixedLayer(still({ now: { ...VIEW, widthPx: 0 } }))).toThrow(/now.widthPx.*got 0/);
    expect(() => planFixedLayer(still({ now: { ...VIEW, heightPx: 240.5 } }))).toThrow(/now.heightPx.*got 240.5/);
  });
});
