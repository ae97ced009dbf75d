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
    omega2: 'ω2 input speed (angular velocity)',
    alpha2: 'α2 input angular acceleration (rad/s²)',
    muBandLo: 'μ band, lower edge (°)',
    muBandHi: 'μ band, upper edge (°)',
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
    omega2: 'ω2',
    alpha2: 'α2',
    muBandLo: 'μ lower edge',
    muBandHi: 'μ upper edge',
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
  rangeWrapped: (lo, hi) => `${lo}° through 0° to ${hi}°`,
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

  sectionMotion: 'Input motion',
  omegaUnit: 'ω2 unit',
  omegaUnits: { 'rad/s': 'rad/s', rpm: 'rpm', 'deg/s': '°/s' },
  showVelocity: 'Velocity vectors',
  showAcceleration: 'Acceleration vectors',
  motionPanelTitle: 'Velocity and acceleration',
  motionAt: (theta2) => `Rates, θ2 = ${theta2}°`,
  angularVelocity: 'Angular velocity ω',
  angularAcceleration: 'Angular acceleration α',
  pointSpeed: (p) => `Speed of ${p}`,
  pointAcceleration: (p) => `Acceleration of ${p}`,
  directionDeg: (deg) => `at ${deg}°`,
  limitPosition: 'limit position',
  motionNoPose: 'The linkage does not assemble at this θ2.',
  motionNote: 'Counter-clockwise positive; ω2 takes the sign of the animation direction.',
  plotKind: 'Plots',
  plotKinds: { angles: 'Angles', velocities: 'Velocities', accelerations: 'Accelerations' },
  chartRates: {
    omega3: 'ω3 against θ2',
    omega4: 'ω4 against θ2',
    omegaBoth: 'ω3 and ω4 against θ2',
    alpha3: 'α3 against θ2',
    alpha4: 'α4 against θ2',
    alphaBoth: 'α3 and α4 against θ2',
  },
  axisOmega: 'ω (rad/s)',
  axisAlpha: 'α (rad/s²)',
  rateFootnote:
    'Rates for the input motion set on the left. Near a limit position they grow without bound: the axis is clipped and ▲ ▼ mark where a curve leaves it.',
  vectorVelocityBar: (v) => `= ${v} length/s`,
  vectorAccelerationBar: (v) => `= ${v} length/s²`,
  vectorZero: 'zero',
  unitSpeed: 'length/s',
  unitAcceleration: 'length/s²',
  vectorClamped: 'dashed: clamped, not to scale',

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
  urlIgnored: (list, count) =>
    count === 1
      ? `This link has a value the simulator cannot use, so the default is shown instead: ${list}.`
      : `This link has ${count} values the simulator cannot use, so the defaults are shown instead: ${list}.`,
  urlIgnoredParam: (key, value) => `${key} = “${value}”`,
  urlIgnoredSeparator: ', ',
  urlIgnoredMore: (count) => `and ${count} more`,
  urlNoticeDismiss: 'Dismiss',

  hardCaseNames: {
    reportCase: 'Report’s crank-rocker',
    toggle180: 'Near toggle, μ → 180°',
    toggle0: 'Near toggle, μ → 0°',
    changePoint: 'Change point, flat at 180°',
    justGrashof: 'Grashof by 1e-12',
    justNonGrashof: 'Non-Grashof by 1e-12',
    parallelogram: 'Parallelogram',
    kiteOnPivot: 'Kite, crank pin on O4',
    kiteFolded: 'Kite that folds flat',
    tripleRockerLimit: 'Triple rocker at its limit',
    tripleRockerGap: 'Triple rocker that avoids 0°',
    doubleRocker: 'Double rocker, two windows',
    limitAt90: 'Limit exactly at 90°',
    dragLinkFlat: 'Drag link, rocker on the ground line',
    tinyCrank: 'Crank of 1e-6',
    longLinks: 'Links of 1e6, crank of 1',
    scaledUp: 'Case 1 × 1e9',
    scaledDown: 'Case 1 × 1e-12',
    vanishingCrank: 'Crank of 1e-300',
    tinyCoupler: 'Coupler of 1e-9',
    cannotAssemble: 'Cannot be assembled',
    singleAssembly: 'Closes at one angle only',
    singularStart: 'Singular NR start',
  },
  hardCaseNotes: {
    reportCase:
      'The report’s worked example: a well-conditioned crank-rocker (μ stays between 47° and 106°) that every method should solve to full precision.',
    toggle180:
      'At θ2 = 180° the transmission angle is 0.002° short of 180°, so the angles hang on the last digits and the report’s 1e-9 test leaves errors up to about 1e-5 rad.',
    toggle0:
      'At θ2 = 0 the coupler and rocker are 0.0015° from folding onto each other (μ → 0): the Jacobian is nearly singular and the half-angle formula’s discriminant nearly zero.',
    changePoint:
      'S + L = P + Q exactly: at θ2 = 180° all four links lie on one line and the two branches meet, so the solver must flag the bifurcation instead of picking a branch silently.',
    justGrashof:
      'Grashof by 1e-12: the two branches pass within a hair of each other at 180°, where a continuation step can land on the wrong one.',
    justNonGrashof:
      'Non-Grashof by 1e-12: θ2 = 180° is unreachable by less than 1e-4°, a gap so narrow that coarse steps skip it unless the solver checks reachability.',
    parallelogram:
      'Two equal pairs: at 0° and 180° the parallelogram and the antiparallelogram cross, and NR can switch from one to the other without warning.',
    kiteOnPivot:
      'At θ2 = 0 the crank pin lands on O4: the coupler and rocker can take any common angle, so the pose is not unique.',
    kiteFolded:
      'Besides the kite, the coupler can fold back onto the crank with the rocker lying on the ground line (θ4 = 180° for every θ2); the crossed branch here is that folded one.',
    tripleRockerLimit:
      'The input stops at ±135.95°, 0.95° from here: a step from 130° to 140° lands where no pose exists, and a careless NR still reports convergence.',
    tripleRockerGap:
      'The input cannot pass through 0° (|θ2| ≥ 57.95°): it rocks on the far side, and the branch changes at each limit.',
    doubleRocker:
      'The coupler is the shortest link: θ2 lives in two separate windows, 38.6° to 78.6° and its mirror, with a limit at each end.',
    limitAt90:
      'The input’s limit is exactly at 90°: the next double above π/2 cannot be assembled, and NR converges only linearly there.',
    dragLinkFlat:
      'Just past θ2 = 60° the rocker lies along the ground line (θ4 ≈ 0° open, −180° crossed), where the half-angle formula divides 0 by 0; 1e-15 rad is still possible.',
    tinyCrank:
      'The crank is a millionth of the other links: the textbook formulas divide by r2 and subtract nearly equal large terms, losing digits that the geometry keeps.',
    longLinks:
      'Links of a million against a crank of 1: the angles are ill-conditioned, and about 1.7e-10 rad is the best any double-precision solver can do.',
    scaledUp:
      'The same angles as case 1, but the residual is never below an absolute 1e-9 at this size, so the report’s NR runs to its iteration limit.',
    scaledDown:
      'The same angles as case 1, but at this size any guess passes an absolute |f| < 1e-9 test, so the report’s NR accepts a wrong first guess.',
    vanishingCrank:
      'A crank of 1e-300 barely moves the linkage; its square underflows to 0, and formulas that divide by r2 overflow and return NaN.',
    tinyCoupler:
      'The coupler is 1e-9 long, so θ2 can only move 6.6e-8° either side of 60°, and about 3e-7 rad is the best accuracy possible.',
    cannotAssemble:
      'The longest link (10) is longer than the other three together (6): a solver must say so at every angle instead of returning NaN or a made-up pose.',
    singleAssembly:
      'The ground equals the sum of the other three: the loop closes only at θ2 = 0, stretched flat, and already 1e-8 rad away it cannot close.',
    singularStart:
      'Started from the guess θ3 = θ4 the Jacobian r3 r4 sin(θ3 − θ4) is exactly zero: NR must report a singular start, not divide by zero.',
  },
  viewSimulator: 'Simulator',
  viewLab: 'Solver lab',
  labTitle: 'Solver lab: speed against error',
  labIntro:
    'Every method below solves the current linkage over a full turn in the worker; errors are measured against a 40-digit reference.',
  labRun: 'Run',
  labRerun: 'Run again',
  labCancel: 'Cancel',
  labProgress: (stage, percent) => `Running: ${stage} (${percent}%)`,
  labCancelled: 'Cancelled. The last finished result stays on screen.',
  labStageReference: '40-digit reference solution',
  labStageSolve: (method, tol) => (tol === null ? method : `${method}, tolerance ${tol}`),
  labStageTiming: (pass, passes, what) => `timing pass ${pass} of ${passes}: ${what}`,
  labStageDone: 'finishing',
  labStatusIdle: 'Not run yet',
  labStatusDone: 'Finished (100%)',
  labStatusCancelled: 'Cancelled',
  labStatusFailed: 'Failed',
  labStep: 'Input step (°)',
  labMethod: 'Method',
  labTolerance: 'Tolerance',
  labToleranceDefault: 'default (full precision)',
  methodNames: {
    'closed-form': 'Closed form',
    'closed-form-polish': 'Closed form + 1 NR polish',
    newton: 'NR continuation + predictor',
    'newton-no-predictor': 'NR continuation, no predictor',
    seed: 'Report’s NR (seed)',
  },
  labTableHeaders: {
    method: 'Method',
    nsPerPoint: 'ns/point',
    itersPerPoint: 'iterations/point',
    maxError: 'max error (rad)',
    p99Error: 'p99 error (rad)',
    failed: 'failed',
    wrongBranch: 'wrong branch',
    falseConvergence: 'false conv.',
  },
  labDiagramTitle: 'Work-precision diagram',
  labDiagramX: 'median time per point (ns)',
  labDiagramY: 'max angle error (rad)',
  labLegendDefault: 'default settings',
  labLegendFailed: 'failed or wrong branch somewhere',
  labPointTooltip: (method, tol, ns, err) => `${method}\ntolerance: ${tol}\n${ns} ns/point\nmax error: ${err} rad`,
  labCycleTitle: 'Iterations and conditioning along the cycle',
  labCycleIterations: 'iterations',
  labCycleDetJ: '|det J| (length²)',
  labNearestLimit: (deg, at) => `Nearest input limit: ${deg}° away (at θ2 = ${at}°)`,
  labNoLimit: 'The crank turns fully: no input limit.',
  labMinSin: (value, at) => `Smallest |sin μ| on the cycle: ${value} at θ2 = ${at}° (conditioning ~ 1/|sin μ|)`,
  labHardCases: 'Hard cases',
  labHardCasesIntro: 'One click loads a linkage that breaks textbook solvers.',
  labChooseNote: 'The method and tolerance chosen here drive the main view.',
  exportLabPng: 'Export diagram PNG',
  exportLabCsv: 'Export diagram CSV',
  labWhatItMeans:
    'How to read it: lower is more accurate and further left is faster, so the closed form, at the bottom left, wins on both. Loose NR tolerances look fast, but their angle error is about the tolerance divided by |sin μ|, which grows without bound near a toggle position. The report’s absolute 1e-9 test stops at about 1e-10 rad and can jump to the other branch.',
  solverRestarted: 'The solver worker stopped; restarted it.',
  solverStoppedTwice: 'Solving on the main thread: the worker stopped twice.',
};
