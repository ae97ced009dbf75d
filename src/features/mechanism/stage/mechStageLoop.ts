import type { MechanismSpec } from '../../../mechanism';
import type { StageFrameHost } from '../../../shared/linkage/liveStage';
import type { Playhead } from '../livePlayhead';
import { playFrame } from '../mechDriveStep';
import type { MechPicture } from '../drawMechanism';
import type { MechScene } from '../mechScene';
import { mechPictureAt, poseDigest, selectedAt } from '../mechScene';
import type { MechDriveRun, MechStageReply, MechStageRequest, MechStageView } from './mechStageProtocol';
import { createStageClock } from '../../../shared/linkage/stageClock';

export { MAX_DT_SECONDS } from '../../../shared/linkage/stageClock';

/** What draws the stage's pictures: the canvas and the view (mechStagePainter.ts in the worker). */
export interface MechStagePainter {
  setCanvas(canvas: OffscreenCanvas): void;
  /** Draws picture in view; how long it took (ms), or null when there is nothing to draw on yet. */
  draw(picture: MechPicture, view: MechStageView): number | null;
}

/** The worker's clock, its animation frames and the way back to the page. */
export type MechStageHost = StageFrameHost<MechStageReply>;

/** Play as it stands: the playhead drawn last and how it moves (its time is the clock's). */
interface Playing {
  id: number;
  playhead: Playhead;
  drive: MechDriveRun;
}

/** A shown picture: the input, or the spec a joint's drag draws. */
interface Shown {
  id: number;
  input: number;
  dragged: MechanismSpec | null;
}

const clampTo = ([lo, hi]: [number, number], t: number) => Math.min(hi, Math.max(lo, t));

/**
 * The Mechanisms page's live stage (the worker's whole behaviour, without its globals): the page's requests
 * (mechStageProtocol.ts) set the canvas, the view and the scene, start Play from a playhead and a time, show one
 * picture (a joint's drag, each move) or stop. Play advances the input itself every animation frame (playFrame, as the
 * page's own loop does: rocking at a limit) and tells the page each frame it drew: the frame it drew, never the one
 * before, so Pause keeps what is on screen. A new scene or view while a picture is shown redraws it. Returns the
 * handler of one request.
 */
export function createMechStageLoop(
  host: MechStageHost,
  painter: MechStagePainter,
): (request: MechStageRequest) => void {
  let scene: MechScene | null = null;
  let view: MechStageView | null = null;
  let playing: Playing | null = null;
  let shown: Shown | null = null;
  let hasCanvas = false;

  /** Draws the scene at input (or the dragged spec); what the page is told of it, or null when nothing was drawn. */
  const draw = (input: number, dragged: MechanismSpec | null, playhead: Playhead) => {
    if (!scene || !view) return null;
    const picture = mechPictureAt(scene, input, dragged);
    const drawMs = painter.draw(picture, view);
    if (drawMs === null) return null;
    return { playhead, pose: poseDigest(picture), selectedAt: selectedAt(picture), drawMs };
  };

  const clock = createStageClock(host, (dt, at) => {
    const p = playing;
    if (!p) return false;
    const { next } = playFrame(p.playhead, p.drive.ratePerS * dt, p.drive.range, p.drive.fullTurn);
    const drawn = draw(clampTo(p.drive.range, next.input), null, next);
    if (!drawn) return false;
    playing = { ...p, playhead: next };
    host.reply({ type: 'drawn', id: p.id, atEpochMs: at, shownEpochMs: at, ...drawn });
    return true;
  });

  /** Draws the shown picture at once (its input came with a page event) and tells the page at the next frame. */
  function drawShown(s: Shown) {
    const drawn = draw(s.input, s.dragged, { input: s.input, direction: 1, limitAt: null });
    if (!drawn) return;
    const at = clock.epochNow();
    clock.atNextFrame(() =>
      host.reply({ type: 'drawn', id: s.id, atEpochMs: at, shownEpochMs: clock.epochNow(), ...drawn }),
    );
  }

  /** Once it has a canvas, a view and a scene, draws the scene once, unseen (compiling the drawing's code), and says so. */
  const warmUp = () => {
    if (clock.readySaid() || !hasCanvas || !scene || !view || !host.requestFrame) return;
    if (!playing && !shown) draw(0, null, { input: 0, direction: 1, limitAt: null });
    clock.sayReady();
  };

  return (m) => {
    switch (m.type) {
      case 'canvas':
        painter.setCanvas(m.canvas);
        hasCanvas = true;
        if (!host.requestFrame) host.reply({ type: 'unsupported' });
        warmUp();
        break;
      case 'view':
      case 'scene':
        if (m.type === 'view') view = m.view;
        else scene = m.scene;
        if (shown) drawShown(shown);
        warmUp();
        break;
      case 'play':
        shown = null;
        playing = { id: m.id, playhead: m.from, drive: m.drive };
        clock.play(m.atEpochMs);
        break;
      case 'show':
        playing = null;
        clock.stop();
        shown = { id: m.id, input: m.input, dragged: m.dragged };
        drawShown(shown);
        break;
      case 'stop':
        playing = null;
        shown = null;
        clock.stop();
        break;
    }
  };
}
