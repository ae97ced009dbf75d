import './LabPanel.css';
import { useCallback, useMemo, useState } from 'react';
import type { Dispatch } from 'react';
import { drawCycleChart } from './cycleChart';
import { drawWorkPrecisionChart, formatTol } from './workPrecisionChart';
import { nearestLimitDeg } from '../../study/limits';
import type { LabPoint, LabResult, LabSeries } from '../../study/workPrecision';
import type { SweepMethod } from '../../solver/types';
import type { Action, AppState } from '../../shared/state/appState';
import { LAB_STEPS_DEG, LAB_TOLERANCES } from '../../study/options';
import { SWEEP_METHODS } from '../../solver/methods';
import type { PngSize } from '../../shared/fileNames';
import { labFileName, labSvgFileName } from '../../shared/fileNames';
import { formatDeg, formatSci } from '../../shared/format';
import { HARD_CASES } from './hardCases';
import { labToCsv } from './labCsv';
import { labProgressStatus } from './labStage';
import type { JobRunner } from '../../shared/jobs/jobClient';
import type { LabJobs } from './jobs';
import { downloadPng, downloadText } from '../../shared/canvas/download';
import { labExport } from './labExport';
import { exportChart } from '../../shared/charts/exportChart';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { labMessagesFor } from './labMessages';
import { Segmented } from '../../shared/ui/Segmented';
import { SvgChartView } from '../../shared/charts/SvgChartView';
import { useLab } from './useLab';

/** Props of LabPanel: the solver client, the app state and its dispatch. */
export interface LabPanelProps {
  client: JobRunner<LabJobs> | null;
  state: AppState;
  dispatch: Dispatch<Action>;
}

/** Logical (CSS pixel) size of the exported work-precision diagram. */
export const LAB_EXPORT_SIZE = { width: 760, height: 460 } as const;

function defaultPoint(s: LabSeries): LabPoint | undefined {
  return s.points.find((p) => p.tol === null);
}

function fmtErr(x: number): string {
  return Number.isFinite(x) ? formatSci(x, 2) : '—';
}

/**
 * The solver lab: a work-precision study of the current linkage computed in the worker (progress,
 * cancel), the per-method counts of failed, wrong-branch and falsely converged points, iterations
 * and |det J| along the cycle, the distance to the nearest limit, the method and tolerance that
 * drive the main view, hard-case presets, and PNG/CSV export of the diagram.
 */
export function LabPanel({ client, state, dispatch }: LabPanelProps) {
  const t = useMessages();
  const lt = labMessagesFor(state.locale);
  const lab = useLab(client, state.linkage, state.branch, state.labStepDeg);
  const [pngSize, setPngSize] = useState<PngSize>('2x');
  const [exportStatus, setExportStatus] = useState('');
  const result: LabResult | null = lab.result;
  const highlight = useMemo(() => ({ method: state.method, tol: state.tol }), [state.method, state.tol]);
  const methodLabels = t.methodNames;

  const chartOptions = useMemo(
    () => ({
      title: lt.labDiagramTitle,
      xLabel: lt.labDiagramX,
      yLabel: lt.labDiagramY,
      highlight,
      methodLabels,
      defaultTolText: lt.labToleranceDefault,
      defaultLegend: lt.labLegendDefault,
      failureLegend: lt.labLegendFailed,
      tooltip: (s: LabSeries, p: LabPoint) =>
        lt.labPointTooltip(
          t.methodNames[s.method],
          formatTol(p.tol, lt.labToleranceDefault),
          p.nsPerPoint.toFixed(0),
          fmtErr(p.maxError),
        ),
      emptyText: t.labRun + '…',
    }),
    [t, lt, highlight, methodLabels],
  );
  const drawDiagram = useCallback(
    (svg: SVGSVGElement, width: number, height: number) =>
      drawWorkPrecisionChart(svg, result ? result.series : [], { ...chartOptions, width, height }),
    [result, chartOptions],
  );
  const drawCycle = useCallback(
    (svg: SVGSVGElement, width: number, height: number) => {
      if (!result) return;
      drawCycleChart(
        svg,
        {
          theta2Deg: result.theta2Deg,
          detJ: result.detJ,
          iterations: result.iterations.map((it) => ({ ...it, label: t.methodNames[it.method] })),
          limitsDeg: result.limitsDeg,
          currentDeg: state.theta2Deg,
        },
        {
          width,
          height,
          title: lt.labCycleTitle,
          xLabel: t.axisTheta2,
          iterationsLabel: lt.labCycleIterations,
          detJLabel: lt.labCycleDetJ,
        },
      );
    },
    [result, t, lt, state.theta2Deg],
  );

  const onPng = async () => {
    if (!result) return;
    setExportStatus('');
    try {
      const { width, height } = LAB_EXPORT_SIZE;
      const bytes = await exportChart(labExport(result.series, { ...chartOptions, width, height }), pngSize);
      downloadPng(bytes, labFileName(result.linkage, result.branch, result.stepDeg, 'png', pngSize));
    } catch (e) {
      setExportStatus(t.exportFailed(e instanceof Error ? e.message : String(e)));
    }
  };
  const onSvg = () => {
    if (!result) return;
    const { width, height } = LAB_EXPORT_SIZE;
    downloadText(
      exportChart(labExport(result.series, { ...chartOptions, width, height }), 'svg'),
      labSvgFileName(result.linkage, result.branch, result.stepDeg),
      'image/svg+xml;charset=utf-8',
    );
  };
  const onCsv = () => {
    if (!result) return;
    downloadText(
      labToCsv(result),
      labFileName(result.linkage, result.branch, result.stepDeg, 'csv'),
      'text/csv;charset=utf-8',
    );
  };

  const nearest = result ? nearestLimitDeg(state.theta2Deg, result.limitsDeg) : null;
  const limitText = !result
    ? null
    : nearest
      ? lt.labNearestLimit(formatDeg(nearest.distanceDeg, 4), formatDeg(nearest.limitDeg, 4))
      : lt.labNoLimit;

  const status = labProgressStatus({ ...lab, hasResult: result !== null }, { ...lt, methodNames: t.methodNames });
  const chosenSeries = result?.series.find((s) => s.method === state.method);
  const chosenPoint = chosenSeries?.points.find((p) => p.tol === state.tol);

  return (
    <div className="lab" data-testid="solver-lab" data-ready={result && !lab.running ? 'true' : 'false'}>
      <section className="card lab-card" aria-labelledby="lab-title">
        <h2 id="lab-title" className="section-title">
          {lt.labTitle}
        </h2>
        <p className="note">{lt.labIntro}</p>
        <div className="lab-toolbar">
          <Segmented<string>
            legend={lt.labStep}
            value={String(state.labStepDeg)}
            options={LAB_STEPS_DEG.map((s) => ({ value: String(s), label: `${s}°` }))}
            onChange={(v) => dispatch({ type: 'setLabStep', stepDeg: Number(v) })}
          />
          {lab.running ? (
            <button type="button" className="btn btn-small" onClick={lab.cancel}>
              {lt.labCancel}
            </button>
          ) : (
            <button type="button" className="btn btn-small btn-primary" onClick={lab.run} disabled={!client}>
              {result ? lt.labRerun : t.labRun}
            </button>
          )}
          <div className="lab-progress">
            <progress max={100} value={status.percent} aria-label={lt.labTitle} aria-valuetext={status.text} />
            <span className="status-line" role="status" aria-live="polite">
              {lab.running ? status.text : lab.cancelled ? lt.labCancelled : (lab.error ?? '')}
            </span>
          </div>
        </div>
        <SvgChartView draw={drawDiagram} label={lt.labDiagramTitle} className="lab-diagram" testId="work-precision" />
        <div className="lab-table-wrap">
          <table className="lab-table">
            <thead>
              <tr>
                <th scope="col">{lt.labTableHeaders.method}</th>
                <th scope="col">{lt.labTableHeaders.nsPerPoint}</th>
                <th scope="col">{lt.labTableHeaders.itersPerPoint}</th>
                <th scope="col">{lt.labTableHeaders.maxError}</th>
                <th scope="col">{lt.labTableHeaders.failed}</th>
                <th scope="col">{lt.labTableHeaders.wrongBranch}</th>
                <th scope="col">{lt.labTableHeaders.falseConvergence}</th>
              </tr>
            </thead>
            <tbody>
              {(result?.series ?? []).flatMap((s) => {
                const rows: Array<{ p: LabPoint; chosen: boolean }> = [];
                const d = defaultPoint(s);
                if (d) rows.push({ p: d, chosen: s.method === state.method && state.tol === null });
                if (s.method === state.method && state.tol !== null && chosenPoint)
                  rows.push({ p: chosenPoint, chosen: true });
                return rows.map(({ p, chosen }) => (
                  <tr key={`${s.method}-${p.tol}`} className={chosen ? 'chosen' : undefined}>
                    <th scope="row">
                      {t.methodNames[s.method]}
                      {p.tol !== null ? `, tol ${formatTol(p.tol)}` : ''}
                    </th>
                    <td className="mono">{p.nsPerPoint.toFixed(0)}</td>
                    <td className="mono">{p.itersPerPoint.toFixed(2)}</td>
                    <td className="mono">{fmtErr(p.maxError)}</td>
                    <td className={`mono${p.failures ? ' bad' : ''}`}>{p.failures}</td>
                    <td className={`mono${p.wrongBranch ? ' bad' : ''}`}>{p.wrongBranch}</td>
                    <td className={`mono${p.falseConvergence ? ' bad' : ''}`}>{p.falseConvergence}</td>
                  </tr>
                ));
              })}
            </tbody>
          </table>
        </div>
        <div className="lab-choose">
          <label className="field-inline">
            <span>{lt.labMethod}</span>
            <select
              className="select"
              aria-label={lt.labMethod}
              value={state.method}
              onChange={(e) => dispatch({ type: 'setMethod', method: e.target.value as SweepMethod, tol: state.tol })}
            >
              {SWEEP_METHODS.map((m) => (
                <option key={m} value={m}>
                  {t.methodNames[m]}
                </option>
              ))}
            </select>
          </label>
          <label className="field-inline">
            <span>{lt.labTolerance}</span>
            <select
              className="select"
              aria-label={lt.labTolerance}
              value={state.tol === null ? 'default' : String(state.tol)}
              disabled={state.method === 'closed-form' || state.method === 'closed-form-polish'}
              onChange={(e) =>
                dispatch({
                  type: 'setMethod',
                  method: state.method,
                  tol: e.target.value === 'default' ? null : Number(e.target.value),
                })
              }
            >
              <option value="default">{lt.labToleranceDefault}</option>
              {LAB_TOLERANCES.map((x) => (
                <option key={x} value={String(x)}>
                  {formatTol(x)}
                </option>
              ))}
            </select>
          </label>
          <p className="note note-muted">{lt.labChooseNote}</p>
        </div>
        {result ? (
          <>
            <p className="note" data-testid="lab-limit">
              {limitText}
            </p>
            <p className="note">
              {lt.labMinSin(formatSci(result.minSinMu.value, 3), formatDeg(result.minSinMu.theta2Deg, 2))}
            </p>
          </>
        ) : null}
        <SvgChartView draw={drawCycle} label={lt.labCycleTitle} className="lab-cycle" />
        <div className="export-buttons lab-export">
          <Segmented<PngSize>
            legend={t.exportSize}
            value={pngSize}
            options={[
              { value: 'screen', label: t.sizeScreen },
              { value: '2x', label: t.size2x },
              { value: 'print', label: t.sizePrint },
            ]}
            onChange={setPngSize}
          />
          <button type="button" className="btn btn-small" onClick={() => void onPng()} disabled={!result}>
            {lt.exportLabPng}
          </button>
          <button type="button" className="btn btn-small" onClick={onSvg} disabled={!result}>
            {t.exportLabSvg}
          </button>
          <button type="button" className="btn btn-small" onClick={onCsv} disabled={!result}>
            {lt.exportLabCsv}
          </button>
          <span className="status-line" role="status">
            {exportStatus}
          </span>
        </div>
        <p className="note">{lt.labWhatItMeans}</p>
      </section>
      <section className="card lab-card" aria-labelledby="lab-hard">
        <h2 id="lab-hard" className="section-title">
          {lt.labHardCases}
        </h2>
        <p className="note">{lt.labHardCasesIntro}</p>
        <ul className="hard-cases">
          {HARD_CASES.map((c) => (
            <li key={c.id}>
              <button
                type="button"
                className="hard-case"
                onClick={() =>
                  dispatch({
                    type: 'applyPreset',
                    linkage: c.linkage,
                    theta2Deg: c.theta2Deg,
                    branch: c.branch,
                    coupler: { distance: c.linkage.r3 / 2, angleDeg: 30 },
                  })
                }
              >
                <span className="hard-case-name">
                  {c.number}. {lt.hardCaseNames[c.id]}
                </span>
                <span className="hard-case-note">{lt.hardCaseNotes[c.id]}</span>
              </button>
            </li>
          ))}
        </ul>
      </section>
    </div>
  );
}
