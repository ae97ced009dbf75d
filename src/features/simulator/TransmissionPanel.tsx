import type { XMark } from '../../shared/charts/xMarks';
import { useMemo } from 'react';
import type { CycleDegrees } from '../../shared/charts/chartInputs';
import { useFramePose } from '../../shared/linkage/FramePoseContext';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { TransmissionChartView } from '../../shared/charts/TransmissionChartView';
import { muMarker, transmissionData, transmissionInputs } from '../../shared/charts/transmissionInputs';

/** Props of TransmissionPanel: the cycle in degrees, the band (degrees) and the dead-centre rules (the marker is the frame on screen). */
export interface TransmissionPanelProps {
  deg: CycleDegrees | null;
  muBandLoDeg: number;
  muBandHiDeg: number;
  xMarks: readonly XMark[];
}

/** The transmission-angle plot: mu against theta2 with the usable band (loaded on demand, with its chart). */
export function TransmissionPanel({ deg, muBandLoDeg, muBandHiDeg, xMarks }: TransmissionPanelProps) {
  const t = useMessages();
  const { state, marker: point } = useFramePose();
  const {
    design: { branch },
  } = state;
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
