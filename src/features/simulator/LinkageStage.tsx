import { useEffect, useLayoutEffect, useMemo } from 'react';
import type { AppState, ViewOffset, CouplerPoint } from '../../shared/state/appState';
import type { CycleResponse } from '../../shared/solution';
import { useFrameSelect } from '../../shared/linkage/FramePoseContext';
import { LinkageCanvas } from './LinkageCanvas';
import { useMessages } from '../../shared/i18n/MessagesContext';
import type { DesignInfo } from './useDesignMetrics';
import { createSceneBuilder } from './scene/sceneBuilder';
import type { ShownFrame } from '../../shared/linkage/shownFrame';
import type { ForceLayer } from '../../shared/linkage/forceVectors';
import type { FramePose } from '../../shared/linkage/FramePoseContext';
import type { LiveStage } from '../../shared/linkage/liveStage';
import { posedState } from './scene/framePose';
import { poseAsPoint } from '../../shared/linkage/localPose';
import { useStageShowing } from './useStageShowing';

/** Props of LinkageStage: the latest cycle and design facts, the canvas's callbacks and hint, and a scene report. */
export interface LinkageStageProps {
  cycle: CycleResponse | null;
  design: DesignInfo | null;
  onViewChange: (view: ViewOffset) => void;
  /** Sets θ2 (degrees) from a drag of A or the arrow keys; omit when locked. */
  onTheta2?: (theta2Deg: number) => void;
  /** Moves the coupler point from a drag of P; omit when locked. */
  onCoupler?: (coupler: CouplerPoint) => void;
  onSize?: (width: number, height: number) => void;
  hint: string;
  /** Called with every frame drawn (the exports draw what is on screen). */
  onShown?: (frame: ShownFrame) => void;
  /** Pin forces to draw for the frame (the app feeds the forces feature's layer); default none. */
  forceLayer?: ForceLayer;
  /** The live stage that draws Play's frames in a worker (null where there is none: the page draws them). */
  stage?: LiveStage | null;
}

/**
 * The frame the page's canvas draws: the frame on screen, or while the live stage draws Play the committed state's
 * (under the stage's canvas: it then redraws only when the state commits, not every frame). The stage is told what
 * it draws from (the committed state, the cycle, the ghost) as they change.
 */
function useStageFrame(stage: LiveStage | null | undefined, cycle: CycleResponse | null): FramePose {
  const showing = useStageShowing(stage);
  const committed = useFrameSelect(committedOf);
  const ghostShown = useFrameSelect(ghostShownOf);
  // Every frame of Play while the page draws it; while the stage shows, nothing (no render per frame).
  const framed = useFrameSelect(showing ? nothingOf : wholeFrameOf);
  useEffect(() => stage?.setScene(committed, cycle, ghostShown), [stage, committed, cycle, ghostShown]);
  // Posed only while the stage shows, once per commit (otherwise the frame on screen is the committed state's).
  return useMemo(() => framed ?? underStageFrame(committed, ghostShown), [framed, committed, ghostShown]);
}

/** The committed state's frame, drawn on the page's canvas under the stage's. */
function underStageFrame(committed: AppState, ghostShown: boolean): FramePose {
  const { local, motion } = posedState(committed, ghostShown);
  const { method, tol } = committed.solver;
  return { state: committed, local, motion, marker: poseAsPoint(local, { method, tol }), committed, ghostShown };
}

const committedOf = (f: FramePose) => f.committed;
const ghostShownOf = (f: FramePose) => f.ghostShown;
const wholeFrameOf = (f: FramePose): FramePose | null => f;
const nothingOf = (): FramePose | null => null;

/**
 * The linkage canvas for the frame on screen (useFramePose): the scene with its design overlay, motion vectors
 * and pin forces (when given a force layer), built and drawn every frame of Play without the rest of the layout
 * re-rendering.
 */
export function LinkageStage({
  cycle,
  design,
  onViewChange,
  onTheta2,
  onCoupler,
  onSize,
  hint,
  onShown,
  forceLayer,
  stage = null,
}: LinkageStageProps) {
  const t = useMessages();
  const { state, local, marker, motion } = useStageFrame(stage, cycle);
  // The one scene pipeline (the live stage's worker builds its frames with the same builder).
  const build = useMemo(() => createSceneBuilder(), []);
  const { scene, description } = useMemo(
    () => build({ state, local, motion, cycle, design, t, forceLayer }),
    [build, state, local, motion, cycle, design, t, forceLayer],
  );
  useLayoutEffect(() => onShown?.({ state, marker, motion, scene }), [state, marker, motion, scene, onShown]);
  return (
    <LinkageCanvas
      scene={scene}
      view={state.display.view}
      onViewChange={onViewChange}
      onTheta2={onTheta2}
      onCoupler={onCoupler}
      onSize={onSize}
      description={description}
      hint={hint}
      stage={stage}
    />
  );
}
