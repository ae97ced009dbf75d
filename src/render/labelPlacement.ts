import type { Px, ScreenRect } from './rect';
import { inflateRect, rectAround, rectInside, rectsOverlap, segmentHitsRect } from './rect';

/**
 * Something a label had better not cover, with a weight: a box (a joint, a pivot) or a thick segment (a link).
 * An obstacle with an owner does not count against that label (an angle label may touch its own arc).
 */
export type Obstacle =
  | { kind: 'rect'; rect: ScreenRect; weight: number; owner?: string }
  | { kind: 'segment'; a: Px; b: Px; halfWidth: number; weight: number; owner?: string };

/** A label to place: its box size (CSS pixels) and the centres it may take, best first. */
export interface LabelRequest<Id extends string> {
  id: Id;
  width: number;
  height: number;
  candidates: readonly Px[];
  /** Placed even when every candidate collides (at its first candidate): for the can't-assemble warning. */
  required?: boolean;
}

/** Where a label went: its box and centre (CSS pixels), which candidate and how much obstacle weight it covers. */
export interface Placement<Id extends string> {
  id: Id;
  box: ScreenRect;
  centre: Px;
  candidateIndex: number;
  cost: number;
}

/** Placed labels in placement order, and the ids of labels that found no free spot. */
export interface PlacementResult<Id extends string> {
  placed: Placement<Id>[];
  dropped: Id[];
}

function obstacleCost(id: string, box: ScreenRect, obstacles: readonly Obstacle[]): number {
  let cost = 0;
  for (const o of obstacles) {
    if (o.owner === id) continue;
    const hit =
      o.kind === 'rect' ? rectsOverlap(box, o.rect) : segmentHitsRect(o.a, o.b, inflateRect(box, o.halfWidth));
    if (hit) cost += o.weight;
  }
  return cost;
}

/**
 * Greedy label placement, in the order given (most important first). A candidate is free when its box lies
 * inside bounds and overlaps neither an exclusion rectangle (e.g. the zoom buttons) nor a label placed before;
 * among free candidates the one covering the least obstacle weight wins, ties going to the earlier candidate.
 * A label with no free candidate is dropped, unless required. So no two placed boxes overlap, and none overlaps
 * an exclusion, except a required label that had no free spot.
 */
export function placeLabels<Id extends string>(
  requests: readonly LabelRequest<Id>[],
  bounds: ScreenRect,
  exclusions: readonly ScreenRect[],
  obstacles: readonly Obstacle[],
): PlacementResult<Id> {
  const placed: Placement<Id>[] = [];
  const dropped: Id[] = [];
  for (const req of requests) {
    let best: Placement<Id> | null = null;
    for (let i = 0; i < req.candidates.length; i++) {
      const centre = req.candidates[i];
      if (!Number.isFinite(centre.x) || !Number.isFinite(centre.y)) continue;
      const box = rectAround(centre, req.width, req.height);
      if (!rectInside(box, bounds)) continue;
      if (exclusions.some((e) => rectsOverlap(box, e))) continue;
      if (placed.some((p) => rectsOverlap(box, p.box))) continue;
      const cost = obstacleCost(req.id, box, obstacles);
      if (!best || cost < best.cost) best = { id: req.id, box, centre, candidateIndex: i, cost };
      if (cost === 0) break;
    }
    if (!best && req.required && req.candidates.length > 0) {
      const centre = req.candidates[0];
      const box = rectAround(centre, req.width, req.height);
      best = { id: req.id, box, centre, candidateIndex: 0, cost: obstacleCost(req.id, box, obstacles) };
    }
    if (best) placed.push(best);
    else dropped.push(req.id);
  }
  return { placed, dropped };
}
