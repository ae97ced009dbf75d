/**
 * Per-frame main-thread cost of the motion vectors, in Node (a proxy for `npm run bench:ui`, which measures
 * whole frames in Chromium): for 720 input angles of the report's linkage, the frame's pose, the scene
 * layout and the drawing into a recording 2D context, without vectors and with velocity and acceleration
 * vectors (frameMotion, vectorOverlay and the extra labels). Prints microseconds per frame for each.
 */
import { frameMotion } from '../src/shared/linkage/frameMotion';
import { localPose } from '../src/shared/linkage/localPose';
import { drawLinkage } from '../src/shared/linkage/drawLinkage';
import type { SceneVectors } from '../src/shared/linkage/motionVectors';
import { arrowScale } from '../src/shared/linkage/motionVectors';
import { sceneBounds, scenePose } from '../src/shared/linkage/scene';
import type { LinkageScene } from '../src/shared/linkage/scene';
import { fitView } from '../src/shared/canvas/view';
import { effectiveInputMotion } from '../src/shared/state/inputMotion';
import { RecordingContext, sceneText } from '../tests/shared/linkage/fixtures';

const L = { r1: 6, r2: 2, r3: 5, r4: 5 };
const COUPLER = { distance: 2.5, angleDeg: 30 };
const FRAMES = 720;
const ROUNDS = 7;

function frame(deg: number, withVectors: boolean, ctx: RecordingContext): void {
  const local = localPose(L, deg, 'open', COUPLER, false);
  const pose = scenePose(L, local.pose, local.coupler);
  let vectors: SceneVectors | null = null;
  if (withVectors) {
    const m = frameMotion(local, effectiveInputMotion(10, 0, 1));
    vectors = m && {
      velocity: { A: { x: m.A.vx, y: m.A.vy }, B: { x: m.B.vx, y: m.B.vy }, P: { x: m.P.vx, y: m.P.vy } },
      acceleration: { A: { x: m.A.ax, y: m.A.ay }, B: { x: m.B.ax, y: m.B.ay }, P: { x: m.P.ax, y: m.P.ay } },
      velocityScale: arrowScale(20),
      accelerationScale: arrowScale(200),
      limit: m.limit,
      text: {
        symbol: { v: 'v', a: 'a' },
        velocityBar: (v) => `= ${v} length/s`,
        accelerationBar: (v) => `= ${v} length/s²`,
        zero: 'zero',
        clamped: 'dashed: clamped, not to scale',
        limit: 'limit position',
        formatValue: (x) => String(x),
      },
    };
  }
  const scene: LinkageScene = {
    linkage: L,
    theta2: local.theta2Rad,
    pose,
    ghost: null,
    curves: [],
    showGrid: true,
    showAngles: true,
    showGhost: false,
    showTrace: false,
    text: sceneText('en', false, deg),
    bounds: sceneBounds(L, [], [], [pose]),
    vectors,
  };
  ctx.calls.length = 0;
  drawLinkage(
    ctx as unknown as CanvasRenderingContext2D,
    scene,
    fitView(scene.bounds, 640, 420, { zoom: 1, panX: 0, panY: 0 }),
  );
}

function timePerFrameUs(withVectors: boolean): number {
  const ctx = new RecordingContext();
  const runs: number[] = [];
  for (let r = 0; r < ROUNDS; r++) {
    const t0 = performance.now();
    for (let k = 0; k < FRAMES; k++) frame((360 * k) / FRAMES, withVectors, ctx);
    runs.push(((performance.now() - t0) * 1000) / FRAMES);
  }
  runs.sort((a, b) => a - b);
  return runs[Math.floor(ROUNDS / 2)];
}

timePerFrameUs(false);
timePerFrameUs(true);
const off = timePerFrameUs(false);
const on = timePerFrameUs(true);
console.log(
  `frame work without vectors: ${off.toFixed(1)} us; with velocity and acceleration vectors: ${on.toFixed(1)} us (+${(((on - off) / off) * 100).toFixed(0)} %)`,
);
