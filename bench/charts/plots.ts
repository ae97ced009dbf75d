import { createAngleChart } from '../../src/shared/charts/theta2Chart';
import type { CycleDegrees } from '../../src/shared/charts/chartInputs';
import { angleChartInputs, angleMarker } from '../../src/shared/charts/chartInputs';
import { messagesEn } from '../../src/shared/i18n/messagesEn';
import type { PointResponse } from '../../src/shared/solution';

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
