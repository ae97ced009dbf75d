import { TWO_PI } from '../../solver';
import type { ViewMove } from './viewProtocol';

/** A pointer pressed on the view: its id, place (CSS px) and whether it pans (right button or a modifier held). */
export interface PressedPointer {
  id: number;
  x: number;
  y: number;
  pans: boolean;
}

/** Zoom factor per wheel step of 100 px (deltaY): 1.2× closer for a step up, as the + key. */
const WHEEL_ZOOM_PER_100PX = 1.2;

/** The zoom of a wheel turn of deltaY CSS px (down, deltaY > 0, zooms out): a factor for zoomBy. */
export function wheelZoom(deltaYPx: number): ViewMove {
  return { op: 'zoom', factor: WHEEL_ZOOM_PER_100PX ** (-deltaYPx / 100) };
}

/**
 * The view's pointer gestures, as three's OrbitControls had them (with z up): one pointer turns the view (a drag over
 * the view's height turns it a full turn), a right-button or modified drag pans it (the scene follows the pointer),
 * two pointers pinch to zoom and pan by their midpoint. Pure: fed pointer places, it answers the moves (ViewMove) to
 * post to the scene, so the page drives a view drawn on its own thread or in a worker alike.
 */
export class ViewGestures {
  private readonly pressed = new Map<number, PressedPointer>();

  /** Pointers pressed now. */
  get count(): number {
    return this.pressed.size;
  }

  down(p: PressedPointer): void {
    this.pressed.set(p.id, { ...p });
  }

  up(id: number): void {
    this.pressed.delete(id);
  }

  /** A pressed pointer moved to (x, y) CSS px in a view heightPx high: its moves (none for a pointer not pressed). */
  move(id: number, x: number, y: number, heightPx: number): ViewMove[] {
    const p = this.pressed.get(id);
    if (!p) return [];
    const h = Math.max(1, heightPx);
    if (this.pressed.size >= 2) {
      const [a, b] = [...this.pressed.values()];
      const before = { d: Math.hypot(b.x - a.x, b.y - a.y), mx: (a.x + b.x) / 2, my: (a.y + b.y) / 2 };
      p.x = x;
      p.y = y;
      const after = { d: Math.hypot(b.x - a.x, b.y - a.y), mx: (a.x + b.x) / 2, my: (a.y + b.y) / 2 };
      const moves: ViewMove[] = [];
      if (before.d > 0 && after.d > 0 && after.d !== before.d) moves.push({ op: 'zoom', factor: after.d / before.d });
      if (after.mx !== before.mx || after.my !== before.my)
        moves.push({ op: 'pan', dx: (after.mx - before.mx) / h, dy: -(after.my - before.my) / h });
      return moves;
    }
    const dx = x - p.x;
    const dy = y - p.y;
    p.x = x;
    p.y = y;
    if (dx === 0 && dy === 0) return [];
    return p.pans
      ? [{ op: 'pan', dx: dx / h, dy: -dy / h }]
      : [{ op: 'orbit', dAzimuth: (TWO_PI * dx) / h, dElevation: (TWO_PI * dy) / h }];
  }
}
