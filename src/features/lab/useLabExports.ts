import { useState } from 'react';
import type { LabResult } from '../../study/workPrecision';
import type { PngSize } from '../../shared/fileNames';
import { labFileName, labSvgFileName } from '../../shared/fileNames';
import { downloadPng, downloadText } from '../../shared/canvas/download';
import { exportChart } from '../../shared/charts/exportChart';
import type { Messages } from '../../shared/i18n/messages';
import { labExport } from './labExport';
import { labToCsv } from './labCsv';
import type { LabCharts } from './useLabCharts';

/** Logical (CSS pixel) size of the exported work-precision diagram. */
const LAB_EXPORT_SIZE = { width: 760, height: 460 } as const;

/** The lab's exports: the chosen PNG size, the last failure's text, and the PNG, SVG and CSV downloads. */
export interface LabExports {
  pngSize: PngSize;
  setPngSize: (size: PngSize) => void;
  status: string;
  onPng: () => Promise<void>;
  onSvg: () => void;
  onCsv: () => void;
}

/** Downloads of the last finished study (each does nothing without one); a failed PNG names its error in status. */
export function useLabExports(
  result: LabResult | null,
  chartOptions: LabCharts['chartOptions'],
  t: Messages,
): LabExports {
  const [pngSize, setPngSize] = useState<PngSize>('2x');
  const [status, setStatus] = useState('');
  const onPng = async () => {
    if (!result) return;
    setStatus('');
    try {
      const bytes = await exportChart(labExport(result.series, chartOptions, LAB_EXPORT_SIZE), pngSize);
      downloadPng(bytes, labFileName(result.linkage, result.branch, result.stepDeg, 'png', pngSize));
    } catch (e) {
      setStatus(t.exportFailed(e instanceof Error ? e.message : String(e)));
    }
  };
  const onSvg = () => {
    if (!result) return;
    downloadText(
      exportChart(labExport(result.series, chartOptions, LAB_EXPORT_SIZE), 'svg'),
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
  return { pngSize, setPngSize, status, onPng, onSvg, onCsv };
}
