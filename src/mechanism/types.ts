/** A joint: R, a pin between two links; P, a slider (links[0], the block, slides along a line fixed in links[1]). */
export interface JointSpec {
  /** Unique, e.g. 'O2', 'A'. */
  id: string;
  kind: 'R' | 'P';
  /** The two links it joins; 'ground' is the frame. For P: [block, guide]. */
  links: [string, string];
  /** Where it is in the drawn configuration (any one length unit). */
  x: number;
  y: number;
  /** P only: slide direction in the drawn configuration, radians counter-clockwise from +x. */
  angle?: number;
}

/** A point on a link, given where it is in the drawn configuration. */
export interface TracerSpec {
  id: string;
  link: string;
  x: number;
  y: number;
}

/**
 * A planar linkage of pins and sliders, given in one drawn configuration. The input is the relative motion
 * at one joint, measured from the drawn configuration (input 0 = as drawn): R, rotation of links[1] relative to
 * links[0], radians counter-clockwise; P, slide of links[0] relative to links[1] along the slide direction.
 */
export interface MechanismSpec {
  /** Link names, 'ground' among them. */
  links: string[];
  joints: JointSpec[];
  points?: TracerSpec[];
  input: { joint: string };
}

/** A point's path: position (length unit), velocity (length/s) and acceleration (length/s²) when rates are asked. */
export interface PointSeries {
  x: Float64Array;
  y: Float64Array;
  vx?: Float64Array;
  vy?: Float64Array;
  ax?: Float64Array;
  ay?: Float64Array;
}

/** A link's rotation from the drawn configuration (rad, continuous: not wrapped), rate (rad/s), acceleration (rad/s²). */
export interface LinkSeries {
  angle: Float64Array;
  omega?: Float64Array;
  alpha?: Float64Array;
}

/** A slider's displacement of block relative to guide along its direction from the drawn configuration. */
export interface SliderSeries {
  s: Float64Array;
  v?: Float64Array;
  a?: Float64Array;
}

/** Why a point has or has no pose (see MECHANISM_STATUSES). */
export type MechanismStatus = 'ok' | 'limit' | 'singular' | 'failed';

/** The answer of sweepMechanism: one entry per input, NaN wherever ok[i] is 0. */
export interface MechanismSweep {
  /** 1 where the linkage assembled at inputs[i] (on the drawn branch, reached by continuity). */
  ok: Uint8Array;
  /** Index into MECHANISM_STATUSES: 0 ok, 1 limit (the input cannot go on), 2 singular (drawn pose), 3 failed (no progress). */
  status: Uint8Array;
  /** Every joint; a P joint's point is the block's. */
  joints: Record<string, PointSeries>;
  /** Every tracer. */
  points: Record<string, PointSeries>;
  /** Every moving link. */
  links: Record<string, LinkSeries>;
  /** Every P joint. */
  sliders: Record<string, SliderSeries>;
  /**
   * det J of the constraint Jacobian (lengths divided by the spec's scale) at each pose; its sign is the
   * assembly's. On the dyad path it is computed only when rates are asked (NaN otherwise).
   */
  detJ: Float64Array;
  /** Newton iterations spent reaching each point (its share of the continuation). */
  iterations: Uint16Array;
  /** The power of two lengths were divided by inside the solver. */
  scale: number;
  /** 'dyads': posed in closed form dyad by dyad (iterations 0); 'newton': Newton continuation on all links. */
  method: 'dyads' | 'newton';
}
