import { degToRad } from '../../solver';
import type { ViewMove } from './viewProtocol';

/** Key steps of the view: 5° of orbit, 10 % of the view's height of pan, 1.2× zoom. */
export const ORBIT_STEP = degToRad(5);
export const PAN_STEP = 0.1;
export const ZOOM_STEP = 1.2;

/**
 * A held key moves the view by this many of its steps a second, on the view's own frames. Its repeats come 25 to 33
 * times a second as tasks on the page's thread, so a view stepped by each repeat moves in jerks, and on a busy page
 * fewer of them; 20 steps a second (100° of orbit) is a little slower than a repeating key, easy to stop where wanted.
 */
export const HOLD_STEPS_PER_S = 20;

/** A hold the page hears no repeat of for this long ends by itself (a key's release lost to a change of focus). */
export const HOLD_TIMEOUT_MS = 600;

/**
 * The view's speeds while keys are held: orbit in radians a second (azimuth, elevation), pan in view heights a second
 * (x right, y up), zoom as the natural log of its factor a second (> 0 closer).
 */
export interface ViewRates {
  dAzimuth: number;
  dElevation: number;
  dx: number;
  dy: number;
  lnZoom: number;
}

/** What a view that moves by rates needs (SpatialScene's camera calls). */
export interface MovableView {
  orbitBy(dAzimuth: number, dElevation: number): void;
  panBy(dx: number, dy: number): void;
  zoomBy(factor: number): void;
}

/** Makes one move of the camera on view. */
export function applyMove(view: MovableView & { resetView(): void }, m: ViewMove): void {
  if (m.op === 'orbit') view.orbitBy(m.dAzimuth, m.dElevation);
  else if (m.op === 'zoom') view.zoomBy(m.factor);
  else if (m.op === 'pan') view.panBy(m.dx, m.dy);
  else view.resetView();
}

/** The view's step for one press of key (arrows orbit, or pan with shift; + = and - zoom; 0 resets), or null. */
export function keyStep(key: string, shift: boolean): ViewMove | null {
  switch (key) {
    case 'ArrowLeft':
      return shift ? { op: 'pan', dx: -PAN_STEP, dy: 0 } : { op: 'orbit', dAzimuth: -ORBIT_STEP, dElevation: 0 };
    case 'ArrowRight':
      return shift ? { op: 'pan', dx: PAN_STEP, dy: 0 } : { op: 'orbit', dAzimuth: ORBIT_STEP, dElevation: 0 };
    case 'ArrowUp':
      return shift ? { op: 'pan', dx: 0, dy: PAN_STEP } : { op: 'orbit', dAzimuth: 0, dElevation: ORBIT_STEP };
    case 'ArrowDown':
      return shift ? { op: 'pan', dx: 0, dy: -PAN_STEP } : { op: 'orbit', dAzimuth: 0, dElevation: -ORBIT_STEP };
    case '+':
    case '=':
      return { op: 'zoom', factor: ZOOM_STEP };
    case '-':
      return { op: 'zoom', factor: 1 / ZOOM_STEP };
    case '0':
      return { op: 'reset' };
    default:
      return null;
  }
}

/** What a key's press asks of the view: a step now (a first press), or nothing (a repeat: the key is held). */
export interface KeyDown {
  /** The key is one of the view's. */
  handled: boolean;
  /** The move to make at once; null for a repeat (a held key moves the view by rates). */
  step: ViewMove | null;
  /** The held keys changed: rates() is new. */
  changed: boolean;
}

/**
 * The view's keys as they are held (pure; SpatialView feeds it the key events). A first press steps the view once; from
 * the key's first repeat on, the key is held and the view moves at HOLD_STEPS_PER_S of its steps a second on the view's
 * own frames until the key is released (held keys add up: right and up turn diagonally). Reset never repeats.
 */
export class KeyHold {
  private readonly held = new Map<string, ViewMove>();

  /**
   * A key pressed: id names the physical key (its release may carry another key value, as '=' for a '+' whose shift
   * went up first), key its value; repeat is the browser's auto-repeat of a held key.
   */
  down(id: string, key: string, shift: boolean, repeat: boolean): KeyDown {
    const step = keyStep(key, shift);
    if (!step) return { handled: false, step: null, changed: false };
    if (!repeat) return { handled: true, step, changed: false };
    if (step.op === 'reset' || this.held.has(id)) return { handled: true, step: null, changed: false };
    this.held.set(id, step);
    return { handled: true, step: null, changed: true };
  }

  /** The key id released; true when it was held (the rates changed). */
  up(id: string): boolean {
    return this.held.delete(id);
  }

  /** Every key let go (focus lost, no repeat heard); true when any was held. */
  clear(): boolean {
    const any = this.held.size > 0;
    this.held.clear();
    return any;
  }

  /** Keys held now. */
  get size(): number {
    return this.held.size;
  }

  /** The view's speeds for the keys held, or null when none is. */
  rates(): ViewRates | null {
    if (this.held.size === 0) return null;
    const r: ViewRates = { dAzimuth: 0, dElevation: 0, dx: 0, dy: 0, lnZoom: 0 };
    for (const m of this.held.values()) {
      if (m.op === 'orbit') {
        r.dAzimuth += m.dAzimuth * HOLD_STEPS_PER_S;
        r.dElevation += m.dElevation * HOLD_STEPS_PER_S;
      } else if (m.op === 'pan') {
        r.dx += m.dx * HOLD_STEPS_PER_S;
        r.dy += m.dy * HOLD_STEPS_PER_S;
      } else if (m.op === 'zoom') r.lnZoom += Math.log(m.factor) * HOLD_STEPS_PER_S;
    }
    return r;
  }
}

/** Moves view by rates over dtS seconds (a frame of a hold): only the calls whose speed is not 0. */
export function moveByRates(view: MovableView, rates: ViewRates, dtS: number): void {
  if (rates.dAzimuth !== 0 || rates.dElevation !== 0) view.orbitBy(rates.dAzimuth * dtS, rates.dElevation * dtS);
  if (rates.dx !== 0 || rates.dy !== 0) view.panBy(rates.dx * dtS, rates.dy * dtS);
  if (rates.lnZoom !== 0) view.zoomBy(Math.exp(rates.lnZoom * dtS));
}
