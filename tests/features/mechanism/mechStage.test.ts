import { afterEach, describe, expect, it, vi } from 'vitest';
import { MECHANISM_TEMPLATES } from '../../../src/mechanism';
import type { MechanismSpec } from '../../../src/mechanism';
import { analyseMechanism, runRange } from '../../../src/features/mechanism/mechAnalysis';
import type { MechPicture } from '../../../src/features/mechanism/drawMechanism';
import type { MechScene } from '../../../src/features/mechanism/mechScene';
import { mechPictureAt, poseDigest, selectedAt } from '../../../src/features/mechanism/mechScene';
import { moveJoint } from '../../../src/features/mechanism/specEdits';
import { handRunFrames } from '../../shared/linkage/handRunFrames';
import { MAX_DT_SECONDS, createMechStageLoop } from '../../../src/features/mechanism/stage/mechStageLoop';
import type { MechStagePainter } from '../../../src/features/mechanism/stage/mechStageLoop';
import type {
  MechStageReply,
  MechStageRequest,
  MechStageView,
} from '../../../src/features/mechanism/stage/mechStageProtocol';
import { createMechStage } from '../../../src/workers/mechStageClient';

// The Mechanisms page's live stage without a worker: its loop on a hand-run clock and animation frames, a painter that
// records what it is asked to draw, and the page's client where a browser cannot hand a canvas to a worker.

const FOUR_BAR = MECHANISM_TEMPLATES.fourBar.spec;
/** The 6-2-5-5 four-bar's crank: 2 long about O2 = (0, 0), along +x as drawn (input 0). */
const CRANK = 2;
/**
 * Poses come from the 1° grid by linear interpolation: a point on a circle of radius r is off its arc by at most
 * r (1 − cos 0.5°) ≈ 3.8e-5 r between two samples; 1e-4 of the crank is well above that and far below a wrong angle.
 */
const GRID_TOL = 1e-4 * CRANK;
const VIEW: MechStageView = {
  bounds: { minX: -3, minY: -3, maxX: 8, maxY: 6 },
  offset: { zoom: 1, panX: 0, panY: 0 },
  width: 400,
  height: 300,
  dpr: 1,
};

function sceneOf(spec: MechanismSpec, selected: string | null = null): MechScene {
  const a = analyseMechanism(spec, false);
  return {
    spec,
    grid: a.grid,
    sweep: a.sweep,
    traces: [],
    slideRange: {},
    selected,
    velocities: [],
    forces: [],
    faint: false,
  };
}

/** A stage loop on a clock the test moves: frames run when the test says, replies and drawn pictures are kept. */
function rig(withFrames = true) {
  const frames = handRunFrames<MechStageReply>(0, withFrames);
  frames.frameAt(1000);
  const drawn: MechPicture[] = [];
  const painter: MechStagePainter = {
    setCanvas: () => {},
    draw(picture) {
      drawn.push(picture);
      return 0.5;
    },
  };
  const handle = createMechStageLoop(frames.host, painter);
  const { replies } = frames;
  return {
    send: (m: MechStageRequest) => handle(m),
    /** Moves the clock by ms and runs the animation frames then due. */
    frame(ms: number) {
      frames.frameAt(frames.now() + ms);
    },
    now: frames.now,
    replies,
    drawn,
    drawnFrames: () => replies.filter((r): r is Extract<MechStageReply, { type: 'drawn' }> => r.type === 'drawn'),
  };
}

const canvas = {} as OffscreenCanvas;

describe('createMechStageLoop', () => {
  it('is ready once it has a canvas, a view and a scene, after one unseen drawing', () => {
    const r = rig();
    r.send({ type: 'canvas', canvas });
    r.send({ type: 'view', view: VIEW });
    expect(r.replies).toEqual([]);
    r.send({ type: 'scene', scene: sceneOf(FOUR_BAR) });
    expect(r.replies).toEqual([{ type: 'ready' }]);
    expect(r.drawn).toHaveLength(1);
  });

  it('says a browser whose workers have no animation frames cannot animate', () => {
    const r = rig(false);
    r.send({ type: 'canvas', canvas });
    expect(r.replies).toEqual([{ type: 'unsupported' }]);
  });

  it('plays on its own clock: each frame draws the crank where the elapsed time puts it', () => {
    const r = rig();
    r.send({ type: 'canvas', canvas });
    r.send({ type: 'view', view: VIEW });
    r.send({ type: 'scene', scene: sceneOf(FOUR_BAR, 'A') });
    const rate = Math.PI / 2; // rad per second
    const start = r.now();
    r.send({
      type: 'play',
      id: 7,
      from: { input: 0.1, direction: 1, limitAt: null },
      atEpochMs: start - 150,
      drive: { ratePerS: rate, range: [-Math.PI, Math.PI], fullTurn: true },
    });
    r.frame(16);
    r.frame(17);
    // A frame 0.5 s late is capped at MAX_DT_SECONDS (a backgrounded tab does not jump).
    r.frame(500);
    const got = r.drawnFrames();
    expect(got.map((f) => f.id)).toEqual([7, 7, 7]);
    // The first step catches up with the page's clock (the play was posted 150 ms before it came: more than a capped
    // step), the others follow each frame.
    const want = [0.1 + rate * 0.166, 0.1 + rate * 0.183, 0.1 + rate * (0.183 + MAX_DT_SECONDS)];
    got.forEach((f, k) => {
      expect(f.playhead.input).toBeCloseTo(want[k], 12);
      expect(f.atEpochMs).toBe(f.shownEpochMs);
      // The chosen crank pin A where the test puts it: 2 (cos t, sin t).
      const [x, y] = f.selectedAt.split(' ').map(Number);
      expect(Math.hypot(x - CRANK * Math.cos(want[k]), y - CRANK * Math.sin(want[k]))).toBeLessThan(GRID_TOL);
      expect(f.pose).toBe(poseDigest(r.drawn[k + 1]));
    });
  });

  it('rocks at a limit: the input stops on the end, reverses and says where', () => {
    const r = rig();
    const scene = sceneOf(FOUR_BAR);
    r.send({ type: 'canvas', canvas });
    r.send({ type: 'view', view: VIEW });
    r.send({ type: 'scene', scene });
    r.send({
      type: 'play',
      id: 1,
      from: { input: 0.45, direction: 1, limitAt: null },
      atEpochMs: r.now(),
      drive: { ratePerS: 1, range: [-0.5, 0.5], fullTurn: false },
    });
    r.frame(100); // 0.1 rad: lands on 0.5, turned
    r.frame(50); // 0.05 back
    const [a, b] = r.drawnFrames().map((f) => f.playhead);
    expect(a).toEqual({ input: 0.5, direction: -1, limitAt: 0.5 });
    expect(b.input).toBeCloseTo(0.45, 12);
    expect(b.direction).toBe(-1);
    expect(b.limitAt).toBe(0.5);
  });

  it('shows a dragged spec as drawn at once, tells the page at the next frame, and redraws it for a new scene', () => {
    const r = rig();
    r.send({ type: 'canvas', canvas });
    r.send({ type: 'view', view: VIEW });
    r.send({ type: 'scene', scene: sceneOf(FOUR_BAR, 'B') });
    const dragged = moveJoint(FOUR_BAR, 'B', 5.25, 4.5);
    r.send({ type: 'show', id: 3, input: 0, dragged });
    expect(r.drawn).toHaveLength(2);
    expect(r.drawnFrames()).toHaveLength(0);
    r.frame(16);
    const [f] = r.drawnFrames();
    expect(f.id).toBe(3);
    expect(f.selectedAt).toBe('5.25 4.5');
    expect(f.shownEpochMs - f.atEpochMs).toBe(16);
    // The drag's rest swept the linkage: a new scene redraws the shown spec (the traces follow while held).
    r.send({ type: 'scene', scene: sceneOf(FOUR_BAR, 'B') });
    expect(r.drawn).toHaveLength(3);
    expect(r.drawn[2].pose.joints.B).toEqual({ x: 5.25, y: 4.5 });
  });

  it('stops: no frame after a stop, and a show stops Play', () => {
    const r = rig();
    r.send({ type: 'canvas', canvas });
    r.send({ type: 'view', view: VIEW });
    r.send({ type: 'scene', scene: sceneOf(FOUR_BAR) });
    const drive = { ratePerS: 1, range: [-Math.PI, Math.PI] as [number, number], fullTurn: true };
    r.send({ type: 'play', id: 1, from: { input: 0, direction: 1, limitAt: null }, atEpochMs: r.now(), drive });
    r.frame(16);
    r.send({ type: 'show', id: 2, input: 0.25, dragged: null });
    r.frame(16);
    r.frame(16);
    const got = r.drawnFrames();
    expect(got.map((f) => f.id)).toEqual([1, 2]);
    expect(got[0].playhead.input).toBeCloseTo(0.016, 12);
    expect(got[1].playhead.input).toBe(0.25);
    r.send({ type: 'play', id: 3, from: { input: 0, direction: 1, limitAt: null }, atEpochMs: r.now(), drive });
    r.send({ type: 'stop' });
    r.frame(16);
    expect(r.drawnFrames()).toHaveLength(2);
  });
});

describe('mechPictureAt', () => {
  it('poses the scene at an input from the sweep, the crank pin on its circle', () => {
    const scene = sceneOf(FOUR_BAR, 'A');
    const range = runRange(analyseMechanism(FOUR_BAR, false))!;
    for (const t of [0, 0.3, 1.7, -2.9, range[1]]) {
      const [x, y] = selectedAt(mechPictureAt(scene, t)).split(' ').map(Number);
      expect(Math.hypot(x - CRANK * Math.cos(t), y - CRANK * Math.sin(t))).toBeLessThan(GRID_TOL);
    }
  });

  it('draws a dragged spec as drawn, without arrows', () => {
    const scene: MechScene = {
      ...sceneOf(FOUR_BAR),
      velocities: [{ id: 'A', x: new Float64Array(361).fill(1), y: new Float64Array(361).fill(2) }],
    };
    expect(mechPictureAt(scene, 0.5).arrows).toHaveLength(1);
    const p = mechPictureAt(scene, 0.5, moveJoint(FOUR_BAR, 'A', 1, 1));
    expect(p.pose.joints.A).toEqual({ x: 1, y: 1 });
    expect(p.arrows).toEqual([]);
  });
});

describe('createMechStage', () => {
  afterEach(() => vi.unstubAllGlobals());

  it('is null where the browser cannot hand a canvas to a worker (the page draws itself)', () => {
    expect(typeof OffscreenCanvas).toBe('undefined');
    expect(createMechStage()).toBeNull();
    // A worker alone is not enough: the canvas must be transferable.
    vi.stubGlobal('Worker', class {});
    expect(createMechStage()).toBeNull();
  });

  /** Browser globals enough for the client: a worker that records its messages, a canvas that can be handed over. */
  function browserLike() {
    const workers: FakeWorker[] = [];
    class FakeWorker extends EventTarget {
      posted: unknown[] = [];
      terminated = false;
      constructor() {
        super();
        workers.push(this);
      }
      postMessage(m: unknown) {
        this.posted.push(m);
      }
      terminate() {
        this.terminated = true;
      }
      answer(data: MechStageReply) {
        this.dispatchEvent(new MessageEvent('message', { data }));
      }
    }
    class FakeCanvas {
      dataset: Record<string, string> = {};
      transferControlToOffscreen() {
        return {};
      }
    }
    vi.stubGlobal('Worker', FakeWorker);
    vi.stubGlobal('OffscreenCanvas', class {});
    vi.stubGlobal('HTMLCanvasElement', FakeCanvas);
    vi.stubGlobal('window', { devicePixelRatio: 1 });
    // The page's next frame comes when the test says (the canvas's attributes follow then).
    const frames: (() => void)[] = [];
    vi.stubGlobal('requestAnimationFrame', (cb: () => void) => frames.push(cb));
    const nextFrame = () => frames.splice(0).forEach((cb) => cb());
    return { workers, canvas: new FakeCanvas() as unknown as HTMLCanvasElement, nextFrame };
  }

  it('follows its run: a frame of the current run shows, a stale one does not, a stop hides it', () => {
    const { workers, canvas: element, nextFrame } = browserLike();
    const stage = createMechStage()!;
    stage.attach(element);
    expect(workers).toHaveLength(1);
    expect(element.dataset.stage).toBe('attached');
    stage.play({ input: 0, direction: 1, limitAt: null }, 0, { ratePerS: 1, range: [-1, 1], fullTurn: false });
    const play = workers[0].posted.at(-1) as Extract<MechStageRequest, { type: 'play' }>;
    const frame = { atEpochMs: 0, shownEpochMs: 0, drawMs: 1, pose: '1.00000', selectedAt: '' };
    workers[0].answer({
      type: 'drawn',
      id: play.id - 1,
      playhead: { input: 9, direction: 1, limitAt: null },
      ...frame,
    });
    expect(stage.showing()).toBe(false);
    expect(stage.latest()).toBeNull();
    const drawn = { input: 0.2, direction: 1 as const, limitAt: null };
    workers[0].answer({ type: 'drawn', id: play.id, playhead: drawn, ...frame });
    expect(stage.showing()).toBe(true);
    expect(stage.latest()).toEqual(drawn);
    nextFrame();
    expect(element.dataset.input).toBe('0.2');
    // A stop names the last frame drawn on the canvas at once, without waiting for a page frame.
    workers[0].answer({ type: 'drawn', id: play.id, playhead: { ...drawn, input: 0.25 }, ...frame });
    stage.stop();
    expect(element.dataset.input).toBe('0.25');
    expect(stage.showing()).toBe(false);
    workers[0].answer({ type: 'drawn', id: play.id, playhead: { ...drawn, input: 0.3 }, ...frame });
    expect(stage.showing()).toBe(false);
  });

  it('hands a new canvas (a remounted view) to the worker it has', () => {
    const { workers, canvas: first } = browserLike();
    const stage = createMechStage()!;
    stage.attach(first);
    const second = new (
      globalThis as unknown as { HTMLCanvasElement: new () => HTMLCanvasElement }
    ).HTMLCanvasElement();
    stage.attach(second);
    expect(workers).toHaveLength(1);
    expect(workers[0].posted.filter((m) => (m as MechStageRequest).type === 'canvas')).toHaveLength(2);
    expect(second.dataset.stage).toBe('attached');
  });

  it('turns itself off for good when its worker fails: the page draws again', () => {
    const { workers, canvas: element } = browserLike();
    const stage = createMechStage()!;
    stage.attach(element);
    stage.show(0, FOUR_BAR);
    const show = workers[0].posted.at(-1) as Extract<MechStageRequest, { type: 'show' }>;
    const frame = { atEpochMs: 0, shownEpochMs: 0, drawMs: 1, pose: '1.00000', selectedAt: '' };
    workers[0].answer({ type: 'drawn', id: show.id, playhead: { input: 0, direction: 1, limitAt: null }, ...frame });
    expect(stage.showing()).toBe(true);
    workers[0].dispatchEvent(new Event('error'));
    expect(stage.usable()).toBe(false);
    expect(stage.showing()).toBe(false);
    expect(workers[0].terminated).toBe(true);
    stage.show(0, FOUR_BAR);
    expect(workers).toHaveLength(1);
  });
});
