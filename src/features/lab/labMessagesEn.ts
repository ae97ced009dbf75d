import type { LabMessages } from './labMessages';

/** English strings of the solver lab. */
export const labMessagesEn: LabMessages = {
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
  labTitle: 'Solver lab: speed against error',
  labIntro:
    'Every method below solves the current linkage over a full turn in the worker; errors are measured against a 40-digit reference.',
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
};
