/// <reference lib="webworker" />
import { applyMove, moveByRates } from '../features/spatial/keyHold';
import type { ViewRates } from '../features/spatial/keyHold';
import { scenePose } from '../features/spatial/sceneData';
import type { SceneLinkage, ScenePose } from '../features/spatial/sceneData';
import { startPlayLoop } from '../features/spatial/playLoop';
import { playStep } from '../features/spatial/spatialPlay';
import type { PlayState } from '../features/spatial/spatialPlay';
import { createSpatialScene } from '../features/spatial/spatialScene';
import type { SpatialScene } from '../features/spatial/spatialScene';
import { PANEL_INTERVAL_MS } from '../features/spatial/spatialPlayhead';
import type { PlayAt, PlayRun, ViewReply, ViewRequest } from '../features/spatial/viewProtocol';

declare const self: DedicatedWorkerGlobalScope;

// The Spatial page's 3D view in a worker (issue 32): three.js on the OffscreenCanvas the page handed over, Play and a
// held key's camera moves on this worker's own animation frames (spatialPlay.ts, keyHold.ts), each drawn frame told to
// the page (its count, and Play's θ2 and branch, which the page's panels follow).
let scene: SpatialScene | null = null;
let linkage: SceneLinkage | null = null;
/** The page's last pose, shown when Play stops. */
let pagePose: ScenePose | null = null;
let run: PlayRun | null = null;
let play: PlayState | null = null;
/** Stops Play's animation-frame loop (playLoop.ts) while it runs. */
let stopLoop: (() => void) | null = null;
/** Where Play turned last (its θ2 and new branch), until the page's run for it comes. */
let lastTurn: { theta2Deg: number; branch: PlayAt['branch'] } | null = null;
/** Where Play is, for the next drawn frame's reply; a turn is kept until a frame carries it. */
let playAt: PlayAt | null = null;

const reply = (m: ViewReply, transfer: Transferable[] = []) => self.postMessage(m, transfer);

/** Frames drawn, when the page was last told (ms), and the timer that tells it of the frames drawn since. */
let frames = 0;
let layerFrames = 0;
let toldAt = Number.NEGATIVE_INFINITY;
let tellTimer: ReturnType<typeof setTimeout> | 0 = 0;

/**
 * Tells the page of the frames drawn (their count, where Play is) at most every PANEL_INTERVAL_MS, as often as its
 * panels follow Play, and of the last one within that: each message is a task on the page's thread, which under a
 * software compositor also handles every frame of the canvas, so the page gets a dozen a second, not one per frame.
 */
function tell(): void {
  const now = performance.now();
  if (now - toldAt < PANEL_INTERVAL_MS) {
    if (!tellTimer) tellTimer = setTimeout(tell, PANEL_INTERVAL_MS - (now - toldAt));
    return;
  }
  clearTimeout(tellTimer);
  tellTimer = 0;
  toldAt = now;
  reply({ type: 'frame', frames, layerFrames, play: playAt });
  if (playAt) playAt = { ...playAt, turned: false };
}

/** The worker's animation frames, for the loops of Play and of a held key (playLoop.ts). */
const frameCalls = {
  request: (f: (nowMs: number) => void) => self.requestAnimationFrame(f),
  cancel: (h: number) => self.cancelAnimationFrame(h),
};

/** One frame of Play (dt seconds since the last): the next pose, drawn in the next animation frame (playLoop.ts). */
function tick(dt: number): void {
  if (!run || !play || !scene || !linkage) return;
  const step = playStep(run.model, run.input, play, dt);
  play = { theta2Deg: step.theta2Deg, branch: step.branch, direction: step.direction };
  playAt = { theta2Deg: step.theta2Deg, branch: step.branch, turned: step.turned || playAt?.turned === true };
  if (step.turned) lastTurn = { theta2Deg: step.theta2Deg, branch: step.branch };
  scene.setPose(step.pose ? scenePose(linkage, step.pose) : null);
}

function setRun(next: PlayRun | null): void {
  run = next;
  if (!next) {
    play = null;
    playAt = null;
    stopLoop?.();
    stopLoop = null;
    scene?.setPose(pagePose);
    return;
  }
  // A new run (Play started, or the linkage or state changed during Play) starts from its θ2 and branch; the
  // direction carries on.
  // The run the page sends back after a turn (the state took the turn's θ2 and branch) carries on from where Play is,
  // which is up to PANEL_INTERVAL_MS past the turn: going back there would jump.
  const afterTurn = lastTurn?.theta2Deg === next.theta2Deg && lastTurn.branch === next.branch;
  lastTurn = null;
  if (afterTurn && play) return;
  play = { theta2Deg: next.theta2Deg, branch: next.branch, direction: play?.direction ?? 1 };
  stopLoop ??= startPlayLoop(frameCalls, tick);
}

/** The held keys' speeds while any is held, and the stop of the loop that moves the camera by them each frame. */
let holdRates: ViewRates | null = null;
let stopHold: (() => void) | null = null;

function setHold(rates: ViewRates | null): void {
  holdRates = rates;
  if (!rates) {
    stopHold?.();
    stopHold = null;
    return;
  }
  stopHold ??= startPlayLoop(frameCalls, (dt) => {
    if (scene && holdRates) moveByRates(scene, holdRates, dt);
  });
}

async function handle(m: ViewRequest): Promise<void> {
  if (m.type === 'init') {
    try {
      if (typeof self.requestAnimationFrame !== 'function') throw new Error('no requestAnimationFrame in a worker');
      scene = createSpatialScene(m.canvas, {
        rendererName: m.rendererName,
        devicePixelRatio: m.devicePixelRatio,
        onFrame: (n, onLayer) => {
          frames = n;
          layerFrames = onLayer;
          tell();
        },
        onQuality: (q, antialias) => reply({ type: 'quality', name: q.name, antialias }),
      });
      reply({ type: 'ready' });
    } catch (e) {
      reply({ type: 'failed', message: e instanceof Error ? e.message : String(e) });
    }
    return;
  }
  if (!scene) return;
  switch (m.type) {
    case 'resize':
      scene.resize(m.widthPx, m.heightPx, m.devicePixelRatio);
      break;
    case 'linkage':
      linkage = m.linkage;
      scene.setLinkage(m.linkage);
      break;
    case 'pose':
      pagePose = m.pose;
      if (!run) scene.setPose(m.pose);
      break;
    case 'projection':
      scene.setProjection(m.projection);
      break;
    case 'move':
      applyMove(scene, m.move);
      break;
    case 'hold':
      setHold(m.rates);
      break;
    case 'play':
      setRun(m.run);
      break;
    case 'png':
      try {
        const bytes = await scene.pngBytes(m.scale);
        reply({ type: 'png', id: m.id, ok: true, bytes }, [bytes.buffer]);
      } catch (e) {
        reply({ type: 'png', id: m.id, ok: false, message: e instanceof Error ? e.message : String(e) });
      }
      break;
  }
}

self.onmessage = (e: MessageEvent<ViewRequest>) => void handle(e.data);
