import type { Locale } from '../../shared/state/appState';
import { messageModule } from '../../shared/i18n/messageModule';

/** Strings of the printable report and its button. */
export interface ReportMessages {
  /** The results column's section that holds the button. */
  section: string;
  /** The button that prints the report. */
  printReport: string;
  /** Beside the button: a PDF comes from the browser's own print dialog. */
  pdfNote: string;
  /** The report's heading. */
  title: string;
  /** Its sections: the figure, the classification, the design metrics, the values at θ2 (degrees, as text), the plots. */
  figure: string;
  classification: string;
  metrics: string;
  atTheta2: (theta2: string) => string;
  plots: string;
  /** The table's column heads. */
  quantity: string;
  value: string;
  /** The figure's caption: the link lengths. */
  lengths: (text: string) => string;
  /** The input and units section, and its facts' labels. */
  setup: string;
  lengthUnit: string;
  omega2: string;
  couplerPoint: string;
  placement: (x: string, y: string, angle: string) => string;
  placementLabel: string;
  targets: string;
  /** The forces section (Forces on). */
  forces: string;
}

const EN: ReportMessages = {
  section: 'Report',
  printReport: 'Print report',
  pdfNote:
    'One page: the figure, the facts, the plots and the values at this θ2. For a PDF, choose “Save as PDF” as the printer in the print dialog.',
  title: 'Four-bar linkage report',
  figure: 'Linkage',
  classification: 'Classification',
  metrics: 'Design metrics',
  atTheta2: (theta2) => `At θ2 = ${theta2}°`,
  plots: 'Plots',
  quantity: 'Quantity',
  value: 'Value',
  lengths: (text) => `Link lengths: ${text}`,
  setup: 'Input and units',
  lengthUnit: 'Length unit',
  omega2: 'Input speed ω2',
  couplerPoint: 'Coupler point',
  placement: (x, y, angle) => `O2 at (${x}, ${y}), ground at ${angle}°`,
  placementLabel: 'Placement',
  targets: 'Targets',
  forces: 'Forces',
};

const ZH_TW: ReportMessages = {
  section: '報告',
  printReport: '列印報告',
  pdfNote: '一頁報告：機構圖、分析結果、圖表與此 θ2 的數值。要存成 PDF，請在列印對話框中選擇「另存為 PDF」作為印表機。',
  title: '四連桿機構報告',
  figure: '機構',
  classification: '分類',
  metrics: '設計指標',
  atTheta2: (theta2) => `θ2 = ${theta2}° 時`,
  plots: '圖表',
  quantity: '物理量',
  value: '數值',
  lengths: (text) => `桿長：${text}`,
  setup: '輸入與單位',
  lengthUnit: '長度單位',
  omega2: '輸入轉速 ω2',
  couplerPoint: '連桿點',
  placement: (x, y, angle) => `O2 位於 (${x}, ${y})，機架角 ${angle}°`,
  placementLabel: '擺放位置',
  targets: '目標點',
  forces: '力',
};

/** The report's strings in every language (small: both bundled). */
const report = messageModule<ReportMessages>(EN, { 'zh-TW': ZH_TW });

/** The report's strings in a language. */
export function reportMessages(locale: Locale): ReportMessages {
  return report.get(locale);
}
