import { useCallback, useRef } from 'react';
import type { AnimationExportResult } from './animation/types';
import type { ShownFrame } from '../../shared/linkage/shownFrame';
import type { AppState } from '../../shared/state/appState';
import type { ExportSubject, PngSize } from '../../shared/fileNames';
import { degToRad } from '../../solver/angles';
import { effectiveInputMotion } from '../../shared/state/inputMotion';
import type { Messages } from '../../shared/i18n/messages';
import type { JobRunner } from '../../shared/jobs/jobClient';
import type { CycleResponse, PointResponse, TableJobs, TableResponse } from '../../shared/solution';
import type { CycleForces } from '../../shared/csv';
import type { AnimationRequest } from './animationExporter';
import type { ExportContext } from './exporters';
import type { CycleDegrees } from '../../shared/charts/chartInputs';
import { useLatest } from '../../shared/hooks/useLatest';

/** What the exports draw: the state, the latest answers, the frame on screen, the cycle in degrees and the strings. */
export interface ExportSources {
  state: AppState;
  /** The worker's point answer (NR runs for the convergence plot). */
  point: PointResponse | null;
  /** The frame the linkage view drew last (null before its first draw): exports show what is on screen. */
  shown: () => ShownFrame | null;
  cycle: CycleResponse | null;
  /** The solver client: the CSV asks it for the full n-point table (the cycle is solved at view resolution). */
  client: JobRunner<TableJobs> | null;
  deg: CycleDegrees | null;
  t: Messages;
  /** The force columns of the table (Forces on), added after the others; absent or null: none. */
  forces?: ((tbl: TableResponse) => CycleForces) | null;
}

/**
 * The frame to export: the one on screen, which is the state's own or Play's a moment ahead of it. A frame
 * drawn for other lengths or another coupler point (edited on the lab page, where no linkage is drawn) is
 * not exported as this linkage: that throws, naming what to do.
 */
function exportFrame({ state, shown, t }: ExportSources): ShownFrame {
  const frame = shown();
  if (
    !frame ||
    frame.state.design.linkage !== state.design.linkage ||
    frame.state.design.coupler !== state.design.coupler
  )
    throw new Error(t.exportNeedsLinkageView);
  return frame;
}

/** Stable export handlers (PNG or SVG of the linkage or a plot, CSV, animation) and the canvas size report they use. */
export interface Exports {
  onPng: (subject: ExportSubject, size: PngSize) => Promise<void>;
  /** Downloads the linkage view or a plot as SVG (text as text). */
  onSvg: (subject: ExportSubject) => Promise<void>;
  onCsv: () => Promise<void>;
  /** Exports one cycle as GIF or WebM and downloads it when done; resolves to the outcome. */
  onAnimation: (request: AnimationRequest) => Promise<AnimationExportResult>;
  /** Give to LinkageCanvas: the linkage PNG is drawn at the on-screen canvas size. */
  onCanvasSize: (width: number, height: number) => void;
}

/** Encodes the animation of the frame on screen at the canvas's size (GIF or WebM, as the request says). */
async function exportAnimation(
  s: ExportSources,
  canvasSize: { width: number; height: number },
  request: AnimationRequest,
): Promise<AnimationExportResult> {
  const { cycle, t } = s;
  const { state, scene } = exportFrame(s);
  if (!cycle) throw new Error('the cycle is still being solved');
  // The frame planner, the encoders and their worker load on the first animation export.
  const { exportLinkageAnimation } = await import('./animationExporter');
  const { width, height } = canvasSize;
  const devicePixelRatio = Math.max(1, Math.min(4, window.devicePixelRatio || 1));
  return exportLinkageAnimation(
    { state, cycle, scene, viewWidth: width, viewHeight: height, devicePixelRatio, t },
    request,
  );
}

/**
 * Solves the n-point table (with the motion columns) on the export channel and downloads it as CSV, with the force
 * columns when given.
 */
async function exportTableCsv({ state: s, client, forces }: ExportSources): Promise<void> {
  if (!client) throw new Error('the solver is still starting');
  // The export always carries the motion columns, for the input motion as the panel shows it.
  const motion = {
    input: effectiveInputMotion(s.motion.omega2RadPerS, s.motion.alpha2RadPerS2, s.motion.direction),
    coupler: { distance: s.design.coupler.distance, angleRad: degToRad(s.design.coupler.angleDeg) },
  };
  const [{ exportCsv }, tbl] = await Promise.all([
    import('./exporters'),
    client.run(
      'table',
      {
        linkage: s.design.linkage,
        samples: s.solver.samples,
        branch: s.design.branch,
        solver: { method: s.solver.method, tol: s.solver.tol },
        motion,
      },
      { channel: 'export' },
    ).result,
  ]);
  // A newer export request superseded this one: it downloads instead.
  if (tbl) exportCsv(tbl, forces?.(tbl) ?? null);
}

/** The export callbacks: stable identities (the export panel does not re-render), always reading the latest sources. */
export function useExports(sources: ExportSources): Exports {
  const canvasSize = useRef({ width: 640, height: 420 });
  const onCanvasSize = useCallback((width: number, height: number) => {
    canvasSize.current = { width, height };
  }, []);
  // Handlers keep one identity (the export panel does not re-render) and read the sources of the last commit.
  const latest = useLatest(sources);
  // The chart builders and writers load on the first export: they are not part of the first load.
  const context = useCallback((): ExportContext => {
    const s = latest.current;
    return { frame: exportFrame(s), point: s.point, deg: s.deg, t: s.t, canvasSize: canvasSize.current };
  }, [latest]);
  const onPng = useCallback(
    async (subject: ExportSubject, size: PngSize) => {
      const c = context();
      const { exportPng } = await import('./exporters');
      await exportPng(subject, size, c);
    },
    [context],
  );
  const onSvg = useCallback(
    async (subject: ExportSubject) => {
      const c = context();
      const { exportSvg } = await import('./exporters');
      exportSvg(subject, c);
    },
    [context],
  );
  const onAnimation = useCallback(
    (request: AnimationRequest) => exportAnimation(latest.current, canvasSize.current, request),
    [latest],
  );
  const onCsv = useCallback(() => exportTableCsv(latest.current), [latest]);
  return { onPng, onSvg, onCsv, onAnimation, onCanvasSize };
}
