// Loaded with a dynamic import on the first animation export: the encoders stay out of the first load.
import { exportAnimation, MAX_FPS } from './animation/animationExport';
import { planAnimationFrames, playbackFps } from './animation/animationFrames';
import type { AnimationSize } from './animation/exportSize';
import { exportSizePx } from './animation/exportSize';
import type { AnimationExportResult, AnimationFormat, ExportProgress, RenderFrame } from './animation/types';
import { downloadBlob } from '../../shared/canvas/download';
import { drawLinkage } from '../../shared/linkage/drawLinkage';
import type { LinkageScene } from '../../shared/linkage/scene';
import { fitScene } from '../../shared/linkage/scene';
import type { AppState } from '../../shared/state/appState';
import { rangeToDeg } from '../../shared/state/animation';
import { animationFileName } from '../../shared/fileNames';
import type { Messages } from '../../shared/i18n/messages';
import type { CycleResponse } from '../../shared/solution';
import { sceneAtFrame } from '../../shared/linkage/frameScene';

/** What the user chose in the Export panel for one animation export. */
export interface AnimationRequest {
  format: AnimationFormat;
  size: AnimationSize;
  /** Frames in one cycle, 36..720. */
  framesPerCycle: number;
  loop: boolean;
  signal: AbortSignal;
  onProgress: (p: ExportProgress) => void;
}

/** What the animation is made of: the state, the solved cycle, the scene on screen, its size (CSS pixels), the strings. */
export interface AnimationSources {
  state: AppState;
  cycle: CycleResponse;
  scene: LinkageScene;
  viewWidth: number;
  viewHeight: number;
  devicePixelRatio: number;
  t: Messages;
}

/**
 * Exports one cycle of Play from the current state (planAnimationFrames) with the views on screen, at Play's
 * speed, and downloads the file when it is done. Resolves to the export's outcome; a linkage that assembles
 * at no input angle is 'unsupported' with the reason in the UI language.
 */
export async function exportLinkageAnimation(
  src: AnimationSources,
  req: AnimationRequest,
): Promise<AnimationExportResult> {
  const { state: s, cycle, scene, t } = src;
  const plan = planAnimationFrames({
    theta2Deg: s.motion.theta2Deg,
    direction: s.motion.direction,
    branch: s.design.branch,
    range: rangeToDeg(cycle.classification.inputRange),
    framesPerCycle: req.framesPerCycle,
  });
  if (plan.frames.length === 0) return { status: 'unsupported', reason: t.cannotAssembleAny };
  // A still (zero-width range) has no cycle time: show its one frame for a second.
  const fps = Math.min(MAX_FPS, playbackFps(plan, s.motion.speedDegPerFrame) || 1);
  const frameSource = {
    base: scene,
    coupler: s.design.coupler,
    curves: cycle.curves,
    classification: cycle.classification,
    t,
  };
  const renderFrame: RenderFrame = (ctx, f, w, h) => {
    drawLinkage(
      ctx,
      sceneAtFrame(frameSource, f.theta2Rad, f.branch),
      fitScene(scene, scene.bounds, w, h, s.display.view),
    );
  };
  const { width, height } = exportSizePx(req.size, src.viewWidth, src.viewHeight, src.devicePixelRatio);
  const result = await exportAnimation({
    format: req.format,
    frames: plan.frames,
    width,
    height,
    viewWidth: src.viewWidth,
    viewHeight: src.viewHeight,
    fps,
    loop: req.loop,
    renderFrame,
    signal: req.signal,
    onProgress: req.onProgress,
  });
  if (result.status === 'done') {
    downloadBlob(
      result.blob,
      animationFileName(s.design.linkage, s.design.branch, req.framesPerCycle, req.size, req.format),
    );
  }
  return result;
}
