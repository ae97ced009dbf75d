import type { Px, ScreenRect } from './rect';
import { halfExtentAlong, rectAround, segmentHitsBox } from './rect';

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
export interface LabelPlacement<Id extends string> {
  id: Id;
  box: ScreenRect;
  centre: Px;
  candidateIndex: number;
  cost: number;
}

/** Placed labels in placement order, and the ids of labels that found no free spot. */
export interface PlacementResult<Id extends string> {
  placed: LabelPlacement<Id>[];
  dropped: Id[];
}

/** Obstacle weight under the box (x0, y0)-(x1, y1), not counting the label's own obstacles; stops at limit. */
function obstacleCost(
  id: string,
  x0: number,
  y0: number,
  x1: number,
  y1: number,
  obstacles: readonly Obstacle[],
  limit: number,
): number {
  let cost = 0;
  for (const o of obstacles) {
    if (o.owner === id) continue;
    let hit: boolean;
    if (o.kind === 'rect') hit = boxOverlaps(x0, y0, x1, y1, o.rect);
    else {
      const d = o.halfWidth;
      hit = segmentHitsBox(o.a.x, o.a.y, o.b.x, o.b.y, x0 - d, y0 - d, x1 + d, y1 + d);
    }
    if (hit) {
      cost += o.weight;
      if (cost >= limit) return cost;
    }
  }
  return cost;
}

/** True when the box (x0, y0)-(x1, y1) shares interior area with r. */
function boxOverlaps(x0: number, y0: number, x1: number, y1: number, r: ScreenRect): boolean {
  return x0 < r.x + r.width && r.x < x1 && y0 < r.y + r.height && r.y < y1;
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
  const placed: LabelPlacement<Id>[] = [];
  const dropped: Id[] = [];
  for (const req of requests) {
    let best: LabelPlacement<Id> | null = null;
    const hw = req.width / 2;
    const hh = req.height / 2;
    for (let i = 0; i < req.candidates.length; i++) {
      const centre = req.candidates[i];
      const x0 = centre.x - hw;
      const y0 = centre.y - hh;
      const x1 = centre.x + hw;
      const y1 = centre.y + hh;
      // Inside the bounds (this also rejects NaN centres), clear of exclusions and of placed labels.
      if (!(x0 >= bounds.x && y0 >= bounds.y && x1 <= bounds.x + bounds.width && y1 <= bounds.y + bounds.height))
        continue;
      let blocked = false;
      for (const e of exclusions) if (boxOverlaps(x0, y0, x1, y1, e)) blocked = true;
      for (const p of placed) if (boxOverlaps(x0, y0, x1, y1, p.box)) blocked = true;
      if (blocked) continue;
      const cost = obstacleCost(req.id, x0, y0, x1, y1, obstacles, best ? best.cost : Infinity);
      if (!best || cost < best.cost)
        best = { id: req.id, box: rectAround(centre, req.width, req.height), centre, candidateIndex: i, cost };
      if (cost === 0) break;
    }
    if (!best && req.required && req.candidates.length > 0) {
      const centre = req.candidates[0];
      const box = rectAround(centre, req.width, req.height);
      const cost = obstacleCost(req.id, box.x, box.y, box.x + box.width, box.y + box.height, obstacles, Infinity);
      best = { id: req.id, box, centre, candidateIndex: 0, cost };
    }
    if (best) placed.push(best);
    else dropped.push(req.id);
  }
  return { placed, dropped };
}

/**
 * Candidate centres (CSS pixels) for a width x height label around p: the direction dir (a unit vector, screen
 * y down) turned by each of rotationsRad in order, at each of gapsPx in order beyond clearancePx, so the box's
 * near edge clears p by the gap whichever way it sits (halfExtentAlong). The first candidates are preferred.
 */
export function candidatesAround(
  p: { x: number; y: number },
  dir: { x: number; y: number },
  rotationsRad: readonly number[],
  gapsPx: readonly number[],
  clearancePx: number,
  width: number,
  height: number,
): { x: number; y: number }[] {
  const out: { x: number; y: number }[] = [];
  for (const gap of gapsPx) {
    for (const rot of rotationsRad) {
      const c = Math.cos(rot);
      const s = Math.sin(rot);
      const ux = dir.x * c - dir.y * s;
      const uy = dir.x * s + dir.y * c;
      const d = clearancePx + gap + halfExtentAlong(ux, uy, width, height);
      out.push({ x: p.x + ux * d, y: p.y + uy * d });
    }
  }
  return out;
}
