import { useCallback, useRef } from 'react';
import type { AnimationExportResult } from '../export/types';
import type { LinkageScene } from '../render/scene';
import { degToRad, radToDeg360 } from '../solver/angles';
import type { Branch } from '../solver/types';
import type { AppState } from '../state/appState';
import type { ExportSubject, PngSize } from '../state/fileNames';
import { csvFileName, pngFileName, svgFileName } from '../state/fileNames';
import { effectiveInputMotion } from '../state/inputMotion';
import type { Messages } from '../state/messages';
import type { SolverClient } from '../worker/client';
import type { CycleResponse, PointResponse } from '../worker/protocol';
import { plotSeries } from '../worker/plotSeries';
import { decodeStatuses } from '../worker/statusCodes';
import type { AnimationRequest } from './animationExporter';
import type { CycleDegrees } from './chartInputs';
import { angleChartInputs, angleMarker, convergenceInputs } from './chartInputs';
import type { FrameMotion } from './frameMotion';
import type { RateChartKind } from './rateInputs';
import { plotRates, rateChartInputs, rateMarker } from './rateInputs';
import { useStableCallback } from './useStableCallback';

/** Logical (CSS pixel) size of exported angle plots. */
export const ANGLE_EXPORT_SIZE = { width: 640, height: 360 } as const;
/** Device pixels the exported rate curves are solved at: the 640 px chart at 2x. */
const RATE_EXPORT_PIXELS = 2 * ANGLE_EXPORT_SIZE.width;
/** Logical (CSS pixel) size of the exported convergence plot. */
export const CONVERGENCE_EXPORT_SIZE = { width: 560, height: 340 } as const;

/** The frame the linkage view drew last: its state (Play's frame applied), its pose as a point and its scene. */
export interface ShownFrame {
  state: AppState;
  /** The pose on screen as a point (the plots' marker). */
  marker: PointResponse;
  /** Its velocities and accelerations (the rate plots' marker); null where it does not assemble. */
  motion: FrameMotion | null;
  scene: LinkageScene;
}

/** What the exports draw: the state, the latest answers, the frame on screen, the cycle in degrees and the strings. */
export interface ExportSources {
  state: AppState;
  /** The worker's point answer (NR runs for the convergence plot). */
  point: PointResponse | null;
  /** The frame the linkage view drew last (null before its first draw): exports show what is on screen. */
  shown: () => ShownFrame | null;
  cycle: CycleResponse | null;
  /** The solver client: the CSV asks it for the full n-point table (the cycle is solved at view resolution). */
  client: SolverClient | null;
  deg: CycleDegrees | null;
  t: Messages;
}

/**
 * The frame to export: the one on screen, which is the state's own or Play's a moment ahead of it. A frame
 * drawn for other lengths or another coupler point (edited on the lab page, where no linkage is drawn) is
 * not exported as this linkage: that throws, naming what to do.
 */
function exportFrame({ state, shown, t }: ExportSources): ShownFrame {
  const frame = shown();
  if (!frame || frame.state.linkage !== state.linkage || frame.state.coupler !== state.coupler)
    throw new Error(t.exportNeedsLinkageView);
  return frame;
}

/**
 * The exported ω or α plot (both links in one chart, as the page's "Together" layout) for the frame on screen: the
 * curves solved on the main thread at the export's resolution (they are not solved while no rate plot shows), for
 * the input motion as set and the direction the input turns, the other branch faint when the ghost shows.
 */
export function rateExport(subject: 'omega' | 'alpha', frame: ShownFrame, t: Messages) {
  const s = frame.state;
  const chart: RateChartKind = subject === 'omega' ? 'omegaBoth' : 'alphaBoth';
  const branches: Branch[] = s.showGhost ? ['open', 'crossed'] : [s.branch];
  const input = { omega2: s.omega2RadPerS, alpha2: s.alpha2RadPerS2 };
  const plot = plotSeries(s.linkage, RATE_EXPORT_PIXELS, branches, { method: s.method, tol: s.tol }, input);
  return {
    inputs: rateChartInputs(chart, plotRates(plot, s.direction), s.branch, s.showGhost, t),
    marker: rateMarker(chart, radToDeg360(frame.marker.theta2Rad), frame.motion ? frame.motion.rates : null),
  };
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

/** The export callbacks: stable identities (the export panel does not re-render), always reading the latest sources. */
export function useExports(sources: ExportSources): Exports {
  const canvasSize = useRef({ width: 640, height: 420 });
  const onCanvasSize = useCallback((width: number, height: number) => {
    canvasSize.current = { width, height };
  }, []);
  const onPng = useStableCallback(async (subject: ExportSubject, size: PngSize) => {
    const { point: p, deg: d, t } = sources;
    const frame = exportFrame(sources);
    const { state: s, marker, scene } = frame;
    // The PNG and CSV writers load on the first export: they are not part of the first load.
    const { angleChartPng, convergencePng, downloadPng, linkagePng, rateChartPng } = await import('./exporters');
    const name = pngFileName(s.linkage, s.branch, s.theta2Deg, subject, size);
    let bytes: Uint8Array;
    if (subject === 'linkage') {
      const { width, height } = canvasSize.current;
      bytes = await linkagePng(scene, s.view, width, height, size);
    } else if (subject === 'convergence') {
      const { width, height } = CONVERGENCE_EXPORT_SIZE;
      bytes = await convergencePng(convergenceInputs(p, s.nrStart, t), width, height, size);
    } else if (subject === 'omega' || subject === 'alpha') {
      const { width, height } = ANGLE_EXPORT_SIZE;
      const r = rateExport(subject, frame, t);
      bytes = await rateChartPng(r.inputs, r.marker, width, height, size);
    } else {
      const { width, height } = ANGLE_EXPORT_SIZE;
      bytes = await angleChartPng(
        angleChartInputs(subject, d, s.branch, s.showGhost, t),
        angleMarker(subject, marker),
        width,
        height,
        size,
      );
    }
    downloadPng(bytes, name);
  });
  const onSvg = useStableCallback(async (subject: ExportSubject) => {
    const { point: p, deg: d, t } = sources;
    const frame = exportFrame(sources);
    const { state: s, marker, scene } = frame;
    const { angleChartSvg, convergenceSvg, downloadText, linkageSvg, rateChartSvg } = await import('./exporters');
    let text: string;
    if (subject === 'linkage') {
      const { width, height } = canvasSize.current;
      text = linkageSvg(scene, s.view, width, height);
    } else if (subject === 'convergence') {
      const { width, height } = CONVERGENCE_EXPORT_SIZE;
      text = convergenceSvg(convergenceInputs(p, s.nrStart, t), width, height);
    } else if (subject === 'omega' || subject === 'alpha') {
      const { width, height } = ANGLE_EXPORT_SIZE;
      const r = rateExport(subject, frame, t);
      text = rateChartSvg(r.inputs, r.marker, width, height);
    } else {
      const { width, height } = ANGLE_EXPORT_SIZE;
      text = angleChartSvg(
        angleChartInputs(subject, d, s.branch, s.showGhost, t),
        angleMarker(subject, marker),
        width,
        height,
      );
    }
    downloadText(text, svgFileName(s.linkage, s.branch, s.theta2Deg, subject), 'image/svg+xml;charset=utf-8');
  });
  const onAnimation = useStableCallback(async (request: AnimationRequest) => {
    const { cycle, t } = sources;
    const { state, scene } = exportFrame(sources);
    if (!cycle) throw new Error('the cycle is still being solved');
    // The frame planner, the encoders and their worker load on the first animation export.
    const { exportLinkageAnimation } = await import('./animationExporter');
    const { width, height } = canvasSize.current;
    const devicePixelRatio = Math.max(1, Math.min(4, window.devicePixelRatio || 1));
    return exportLinkageAnimation(
      { state, cycle, scene, viewWidth: width, viewHeight: height, devicePixelRatio, t },
      request,
    );
  });
  const onCsv = useStableCallback(async () => {
    const { state: s, client } = sources;
    if (!client) throw new Error('the solver is still starting');
    // The export always carries the motion columns, for the input motion as the panel shows it.
    const motion = {
      input: effectiveInputMotion(s.omega2RadPerS, s.alpha2RadPerS2, s.direction),
      coupler: { distance: s.coupler.distance, angleRad: degToRad(s.coupler.angleDeg) },
    };
    const [{ downloadCsv }, tbl] = await Promise.all([
      import('./exporters'),
      client.table(
        { linkage: s.linkage, samples: s.samples, branch: s.branch, solver: { method: s.method, tol: s.tol }, motion },
        'export',
      ),
    ]);
    // A newer export request superseded this one: it downloads instead.
    if (!tbl) return;
    downloadCsv(
      {
        theta2Deg: tbl.theta2Deg,
        theta3Rad: tbl.theta3Rad,
        theta4Rad: tbl.theta4Rad,
        status: decodeStatuses(tbl.statusCodes),
        iterations: tbl.iterations,
        residual: tbl.residual,
        motion: tbl.motion ?? null,
      },
      csvFileName(tbl.linkage, tbl.branch, tbl.samples),
    );
  });
  return { onPng, onSvg, onCsv, onAnimation, onCanvasSize };
}
