import type { XMark } from '../../shared/charts/xMarks';
import { useMemo } from 'react';
import type { CycleDegrees } from '../../shared/charts/chartInputs';
import { useFrameDerived, useFrameSelect } from '../../shared/linkage/FramePoseContext';
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
  // Only the branch re-renders the panel; the marker follows the frame on screen by itself.
  const branch = useFrameSelect((f) => f.state.design.branch);
  const data = useMemo(() => transmissionData(deg, branch), [deg, branch]);
  const band = useMemo(() => ({ loDeg: muBandLoDeg, hiDeg: muBandHiDeg }), [muBandLoDeg, muBandHiDeg]);
  const inputs = useMemo(() => transmissionInputs(data, band, xMarks, t), [data, band, xMarks, t]);
  const marker = useFrameDerived((f) => muMarker(f.marker), []);
  return (
    <div className="plots-grid plots-together">
      <TransmissionChartView inputs={inputs} marker={marker} label={t.chartTransmission} />
    </div>
  );
}
