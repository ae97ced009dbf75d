import { drawAngleChart, updateAngleMarker } from '../../src/charts/angleChart';
import type { CycleDegrees } from '../../src/components/chartInputs';
import { angleChartInputs, angleMarker } from '../../src/components/chartInputs';
import { messagesEn } from '../../src/state/messagesEn';
import type { PointResponse } from '../../src/worker/protocol';

/** The two separate angle plots of the main page, driven the way the app drives them (the chart API before the handles). */
export function makeAnglePlots(svgs: SVGSVGElement[], width: number, height: number) {
  const kinds = ['theta3', 'theta4'] as const;
  return {
    update(deg: CycleDegrees, point: PointResponse) {
      kinds.forEach((kind, i) => {
        const inp = angleChartInputs(kind, deg, 'open', false, messagesEn);
        drawAngleChart(svgs[i], inp.data, { width, height, title: inp.title, xLabel: inp.xLabel, yLabel: inp.yLabel });
        updateAngleMarker(svgs[i], angleMarker(kind, point), inp.markerColors);
      });
    },
  };
}
