import type { Messages } from './messages';

/** English UI strings (the default language). */
export const messagesEn: Messages = {
  htmlLang: 'en',
  appTitle: 'Four-bar linkage lab',
  appSubtitle: 'Newton–Raphson position analysis',
  language: 'Language',
  languageNames: { en: 'English', 'zh-TW': '繁體中文' },

  sectionLinks: 'Link lengths',
  sectionInput: 'Input angle',
  sectionCoupler: 'Coupler point P',
  sectionAnimation: 'Animation',
  sectionDisplay: 'Display',
  sectionExport: 'Export',
  sectionShare: 'Share and embed',
  sectionAnalysis: 'Analysis',
  sectionPlots: 'Plots',

  fieldLabels: {
    r1: 'r1 ground',
    r2: 'r2 crank (input)',
    r3: 'r3 coupler',
    r4: 'r4 rocker (output)',
    theta2: 'θ2 input angle (°)',
    couplerDistance: 'P distance from A',
    couplerAngle: 'P angle from AB (°)',
    speed: 'Speed (°/frame)',
  },
  sliderSuffix: 'slider',
  fieldShortNames: {
    r1: 'r1',
    r2: 'r2',
    r3: 'r3',
    r4: 'r4',
    theta2: 'θ2',
    couplerDistance: 'P distance',
    couplerAngle: 'P angle',
    speed: 'Speed',
  },
  fieldError: (e, f) => {
    const name = messagesEn.fieldShortNames[e.field];
    switch (e.kind) {
      case 'empty':
        return `${name}: enter a number.`;
      case 'notNumber':
        return `${name}: “${f.raw}” is not a number.`;
      case 'notPositive':
        return `${name} must be greater than 0, got ${f.raw}.`;
      case 'negative':
        return `${name} must not be negative, got ${f.raw}.`;
      case 'tooSmall':
        return `${name}: ${f.raw} is too small (at least ${f.min}).`;
      case 'tooLarge':
        return `${name}: ${f.raw} is out of range (${f.min} to ${f.max}).`;
    }
  },
  keepingLast: (v) => `Keeping the last valid value, ${v}.`,
  locked: 'locked',

  branch: 'Branch',
  branchOpen: 'Open',
  branchCrossed: 'Crossed',
  play: 'Play',
  pause: 'Pause',
  direction: 'Direction',
  ccw: 'Counter-clockwise',
  cw: 'Clockwise',
  stepBack: 'Step back',
  stepForward: 'Step forward',
  rockingNote: 'The input cannot turn fully: it rocks between its limits and the branch switches at each limit.',

  showGrid: 'Grid',
  showAngles: 'Angle labels',
  showGhost: 'Other branch (ghost)',
  showTrace: 'Coupler curve',
  samples: 'Samples per cycle',

  preset: 'Preset',
  presetPlaceholder: 'Custom linkage',
  presetNames: {
    report: 'Report case 6-2-5-5',
    dragLink: 'Drag link (double crank)',
    doubleRocker: 'Grashof double rocker',
    tripleRocker: 'Triple rocker (non-Grashof)',
    parallelogram: 'Parallelogram',
    nearToggle: 'Near-toggle crank-rocker',
    chebyshevLambda: 'Chebyshev’s lambda',
    hoeckens: 'Hoeckens straight-line',
  },

  grashofCheck: 'Grashof check',
  grashofYes: 'Grashof (S + L < P + Q)',
  grashofNo: 'Non-Grashof (S + L > P + Q)',
  grashofChangePoint: 'Change point (S + L = P + Q)',
  linkageType: 'Type',
  types: {
    'crank-rocker': 'Crank-rocker',
    'double-crank': 'Double crank (drag link)',
    'double-rocker': 'Double rocker',
    'change-point': 'Change point',
    'triple-rocker': 'Triple rocker',
    'cannot-assemble': 'Cannot assemble',
  },
  barker: 'Barker class',
  inputRange: 'Input range θ2',
  fullTurn: 'full turn',
  noRange: 'none',
  rangeInterval: (lo, hi) => `${lo}° to ${hi}°`,
  atTheta2: (t) => `At θ2 = ${t}°`,
  nrIterations: 'NR iterations',
  residual: 'Residual |f|',
  detJ: 'det J',
  status: 'Status',
  newtonStatus: { converged: 'converged', singular: 'singular Jacobian', 'max-iterations': 'iteration limit reached' },
  pointStatus: { ok: 'assembled', unreachable: 'cannot assemble', singular: 'singular', failed: 'failed' },
  transmissionAngle: 'Transmission angle μ',
  cycleSummary: (ok, total, it) => `Cycle: ${ok} of ${total} points assembled, ${it} NR iterations in all`,
  solvingOnMainThread: 'Web Worker unavailable here: solving on the main thread.',

  plotSeparate: 'Separate',
  plotTogether: 'Together',
  plotLayout: 'Angle plots',
  nrStartLabel: 'NR start',
  nrContinuation: 'Continuation',
  nrCold: 'Cold start',
  chartTheta3: 'θ3 against θ2',
  chartTheta4: 'θ4 against θ2',
  chartBoth: 'θ3 and θ4 against θ2',
  chartConvergence: (t) => `NR convergence at θ2 = ${t}°`,
  axisTheta2: 'θ2 (°)',
  axisTheta3: 'θ3 (°)',
  axisTheta4: 'θ4 (°)',
  axisAngle: 'Angle (°)',
  axisIteration: 'Iteration',
  axisResidual: 'Residual |f| (length unit)',
  legendOtherBranch: 'other branch',
  angleFootnote:
    'Angles in degrees, counter-clockwise from the ground line. θ2 runs over one turn, 0° to 360°; θ3, θ4 and μ are wrapped to (−180°, 180°]. Gaps: the linkage cannot assemble there.',
  noConvergenceData: 'No NR run: cannot assemble here.',

  canvasLabel: 'Linkage view',
  cannotAssembleAt: (t) => `Cannot assemble at θ2 = ${t}°`,
  cannotAssembleAny: 'This linkage cannot be assembled at any input angle',
  reachableHint: (r) => `Reachable θ2: ${r}`,
  resetView: 'Reset view',
  zoomIn: 'Zoom in',
  zoomOut: 'Zoom out',
  gridSpacing: (s) => `grid ${s}`,
  jointLabels: { O2: 'O2', O4: 'O4', A: 'A', B: 'B', P: 'P' },

  exportSize: 'PNG size',
  sizeScreen: 'Screen',
  size2x: '2×',
  sizePrint: '300 DPI print',
  exportLinkage: 'Export linkage view PNG',
  exportTheta3: 'Export θ3 plot PNG',
  exportTheta4: 'Export θ4 plot PNG',
  exportBoth: 'Export θ3 and θ4 plot PNG',
  exportConvergence: 'Export NR convergence plot PNG',
  exportCsv: 'Export cycle CSV',
  exportFailed: (r) => `Export failed: ${r}`,

  copyLink: 'Copy link',
  copyEmbed: 'Copy embed code',
  copied: 'Copied to the clipboard.',
  copyFailed: 'The clipboard is not available here: select the text below and copy it.',
  embedPanels: 'Show in the embed',
  embedLock: 'Lock in the embed',
  panelNames: { controls: 'Controls', info: 'Analysis', plots: 'Plots', export: 'Export' },
  lockLengths: 'Link lengths',
  lockAngle: 'Input angle',
  openFull: 'Open the full simulator',
  embedTitle: 'Four-bar linkage simulator',

  errorTitle: 'Something went wrong',
  errorBody: 'The simulator hit an unexpected error. Your last settings are in the address bar.',
  errorReset: 'Reset to the default linkage',
};
