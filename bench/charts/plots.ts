import { createAngleChart } from '../../src/charts/angleChart';
import type { CycleDegrees } from '../../src/components/chartInputs';
import { angleChartInputs, angleMarker } from '../../src/components/chartInputs';
import { messagesEn } from '../../src/state/messagesEn';
import type { PointResponse } from '../../src/worker/protocol';

/** The two separate angle plots of the main page, driven the way AngleChartView drives them: update, then setMarker. */
export function makeAnglePlots(svgs: SVGSVGElement[], width: number, height: number) {
  const kinds = ['theta3', 'theta4'] as const;
  const charts = kinds.map((kind, i) => {
    const inp = angleChartInputs(kind, null, 'open', false, messagesEn);
    return createAngleChart(svgs[i], { width, height, title: inp.title, xLabel: inp.xLabel, yLabel: inp.yLabel });
  });
  return {
    update(deg: CycleDegrees, point: PointResponse) {
      kinds.forEach((kind, i) => {
        charts[i].update(angleChartInputs(kind, deg, 'open', false, messagesEn).data);
        charts[i].setMarker(angleMarker(kind, point));
      });
    },
  };
}
