import { useLayoutEffect, useMemo } from 'react';
import type { ViewOffset, CouplerPoint } from '../../shared/state/appState';
import type { CycleResponse } from '../../shared/solution';
import { useFramePose } from '../../shared/linkage/FramePoseContext';
import { LinkageCanvas } from './LinkageCanvas';
import { useMessages } from '../../shared/i18n/MessagesContext';
import type { DesignInfo } from './useDesignMetrics';
import { useDesignScene } from './useDesignScene';
import { useLinkageScene } from './useLinkageScene';
import { useSceneVectors } from './useSceneVectors';
import type { ShownFrame } from '../../shared/linkage/shownFrame';
import type { ForceLayer } from '../../shared/linkage/forceVectors';

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
}

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
}: LinkageStageProps) {
  const t = useMessages();
  const { state, local, marker, motion } = useFramePose();
  const designScene = useDesignScene(state, local, design, t);
  const vectors = useSceneVectors(state, motion, t);
  const { scene: kinematic, description } = useLinkageScene(state, local, cycle, t, designScene, vectors);
  const forces = useMemo(() => forceLayer?.(state, local) ?? null, [forceLayer, state, local]);
  const scene = useMemo(() => (forces ? { ...kinematic, forces } : kinematic), [kinematic, forces]);
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
    />
  );
}
