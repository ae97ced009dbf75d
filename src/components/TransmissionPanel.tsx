import './TransmissionPanel.css';
import type { XMark } from '../charts/xMarks';
import { useMemo } from 'react';
import type { Branch } from '../solver/types';
import type { PointResponse } from '../worker/protocol';
import type { CycleDegrees } from './chartInputs';
import { useMessages } from './MessagesContext';
import { TransmissionChartView } from './TransmissionChartView';
import { muMarker, transmissionData, transmissionInputs } from './transmissionInputs';

/** Props of TransmissionPanel: the cycle in degrees, the pose, the branch, the band (degrees) and the dead-centre rules. */
export interface TransmissionPanelProps {
  deg: CycleDegrees | null;
  point: PointResponse | null;
  branch: Branch;
  muBandLoDeg: number;
  muBandHiDeg: number;
  xMarks: readonly XMark[];
}

/** The transmission-angle plot: mu against theta2 with the usable band (loaded on demand, with its chart). */
export function TransmissionPanel({ deg, point, branch, muBandLoDeg, muBandHiDeg, xMarks }: TransmissionPanelProps) {
  const t = useMessages();
  const data = useMemo(() => transmissionData(deg, branch), [deg, branch]);
  const band = useMemo(() => ({ loDeg: muBandLoDeg, hiDeg: muBandHiDeg }), [muBandLoDeg, muBandHiDeg]);
  const inputs = useMemo(() => transmissionInputs(data, band, xMarks, t), [data, band, xMarks, t]);
  const marker = useMemo(() => muMarker(point), [point]);
  return (
    <div className="plots-grid plots-together">
      <TransmissionChartView inputs={inputs} marker={marker} label={t.chartTransmission} />
    </div>
  );
}
