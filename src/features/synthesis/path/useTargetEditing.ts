import { useRef, useState } from 'react';
import type { Dispatch, RefObject } from 'react';
import type { Point } from '../../../solver/kinematics';
import { placedJoints } from '../../../synthesis/placed';
import type { PlacedFourBar } from '../../../synthesis/types';
import type { Bounds } from '../../../shared/canvas/view';
import { fitView } from '../../../shared/canvas/view';
import type { Action, ViewOffset } from '../../../shared/state/appState';
import type { SynthesisMessages } from '../synthesisMessages';
import type { PathCurve, PathScene } from './drawPathScene';
import { exportPathPng, exportPathSvg } from './pathExports';

/** The fitted view: no zoom, no pan. */
const FITTED: ViewOffset = { zoom: 1, panX: 0, panY: 0 };

/** The targets' editing (useTargetEditing): the selection, the canvas's view and element, and the edits. */
export interface TargetEditing {
  selected: number | null;
  setSelected: (index: number | null) => void;
  view: ViewOffset;
  setView: (view: ViewOffset) => void;
  /** How many times the targets were replaced: part of the fit's reset key (the canvas refits to new targets). */
  replaced: number;
  /** New targets from a paste, an import or an example, with their θ2 (degrees: the timing becomes "given") or null. */
  replace: (targets: Point[], theta2Deg?: number[] | null) => void;
  /** The canvas element, for the exports (its size in CSS pixels). */
  canvasRef: RefObject<HTMLCanvasElement | null>;
  /** The canvas's edits: a target dragged, a tap that adds one (it becomes the selected one), Delete. */
  onMove: (index: number, p: Point) => void;
  onAdd: (p: Point) => void;
  onRemove: (index: number) => void;
  /** Export SVG and PNG of the canvas as shown: the targets, the curves and the chosen linkage at its θ2 (radians). */
  sceneExports: (
    bounds: Bounds,
    curves: readonly PathCurve[],
    chosen: { design: PlacedFourBar; theta2: number } | null,
  ) => { onExportSvg: () => void; onExportPng: () => void };
}

/**
 * The target handling of the modes that edit targets on the synthesis canvas (Path, Nine points): the selection, the
 * canvas's pan and zoom (back to the fit when the targets are replaced), its moves, adds and removes, and its exports.
 */
export function useTargetEditing(
  targets: readonly Point[],
  dispatch: Dispatch<Action>,
  st: SynthesisMessages,
): TargetEditing {
  const [selected, setSelected] = useState<number | null>(null);
  const [view, setView] = useState<ViewOffset>(FITTED);
  const [replaced, setReplaced] = useState(0);
  const canvasRef = useRef<HTMLCanvasElement>(null);

  const replace = (next: Point[], theta2Deg: number[] | null = null) => {
    dispatch({ type: 'setTargets', targets: next });
    if (theta2Deg) {
      dispatch({ type: 'setGivenTheta2', theta2Deg });
      dispatch({ type: 'setTiming', timing: 'given' });
    }
    setSelected(null);
    setReplaced((n) => n + 1);
    setView(FITTED);
  };
  const onMove = (i: number, p: Point) =>
    dispatch({ type: 'setTargets', targets: targets.map((q, k) => (k === i ? p : q)) });
  const onAdd = (p: Point) => {
    dispatch({ type: 'setTargets', targets: [...targets, p] });
    setSelected(targets.length);
  };
  const onRemove = (i: number) => {
    dispatch({ type: 'removeTarget', index: i });
    setSelected(null);
  };

  const sceneExports: TargetEditing['sceneExports'] = (bounds, curves, chosen) => {
    const scene = () => {
      const canvas = canvasRef.current;
      if (!canvas) return null;
      const pose = chosen ? placedJoints(chosen.design, chosen.theta2) : null;
      const names = targets.map((_, i) => st.targetName(i + 1));
      const scene: PathScene = { targets, selected: null, names, curves, pose };
      return { scene, view: fitView(bounds, canvas.clientWidth, canvas.clientHeight, view) };
    };
    return {
      onExportSvg: () => {
        const e = scene();
        if (e) exportPathSvg(e.scene, e.view);
      },
      onExportPng: () => {
        const e = scene();
        if (e) void exportPathPng(e.scene, e.view);
      },
    };
  };

  return { selected, setSelected, view, setView, replaced, replace, canvasRef, onMove, onAdd, onRemove, sceneExports };
}
