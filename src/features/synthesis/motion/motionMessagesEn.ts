import type { MotionMessages } from './motionMessages';

/** English strings of the Motion mode. */
export const motionMessagesEn: MotionMessages = {
  intro:
    'Place 2 to 20 poses of the coupler: drag a pose’s point to move it and its handle to turn it, or type them in the table.',
  methodFor: {
    2: 'Two poses: the body turns about their pole as a rocker, and a crank swings it between them (two-position rocker synthesis).',
    3: 'Three poses: place two pivots; the other two are the centres of the circles through their three positions.',
    4: 'Four poses: every point of the centre-point curve is a fixed pivot with its moving pivot on the circle-point curve. Pick two.',
    5: 'Five poses: only the Burmester points (at most four) keep a pivot on a circle through all five; each two make a four-bar.',
    6: 'Six or more poses: no four-bar meets them all, so each dyad is the best fit by least squares (its moving pivot’s positions as near a circle as they can be); each two make a four-bar, with its error at every pose.',
  },
  posesTitle: 'Poses',
  poseName: (n) => `Pose ${n}`,
  tableCaption: 'Poses: point and direction',
  columnX: 'x',
  columnY: 'y',
  columnAngle: 'angle (°)',
  addPose: 'Add pose',
  removePose: (n) => `Remove pose ${n}`,
  removeColumn: 'Remove',
  cellError: (cell, text, kept, why) =>
    `${cell}: “${text}” ${why ? `is refused: ${why}` : 'is not a number'}; keeping ${kept}.`,
  mustBePositive: 'it must be above 0',
  mustBeBetween: (min, max) => `it must lie from ${min} to ${max}`,
  canvasLabel: 'Motion synthesis canvas',
  canvasHint:
    'Drag a pose’s point or its handle; drag elsewhere to pan. Keys: 1–9 choose a pose, arrows move it (Shift: finer), [ and ] turn it, + − 0 zoom.',
  zoomIn: 'Zoom in',
  zoomOut: 'Zoom out',
  resetView: 'Fit the view',
  selectedPose: (n, x, y, deg) => `Pose ${n} selected: x ${x}, y ${y}, ${deg}°`,
  pivotLegend: 'Pivots you place',
  pivotMoving: 'Moving pivots',
  pivotFixed: 'Fixed pivots',
  pivotTable: (choice) =>
    choice === 'moving' ? 'Moving pivots A and B (in pose 1’s frame)' : 'Fixed pivots O2 and O4 (in the plane)',
  pivotName: { A: 'moving pivot A', B: 'moving pivot B', O2: 'fixed pivot O2', O4: 'fixed pivot O4' },
  constructionNote: (choice) =>
    choice === 'moving'
      ? 'Dashed: the perpendicular bisectors of each moving pivot’s positions; they meet at its fixed pivot, the centre of its circle.'
      : 'Inversion: seen from the coupler, each fixed pivot takes three positions (drawn at pose 1); the bisectors meet at its moving pivot.',
  centreCurve: 'Centre-point curve',
  circleCurve: 'Circle-point curve',
  pickHint:
    'Click or tap a point of the centre-point curve to pick a dyad, or choose one below; two dyads make a linkage.',
  picked: (n) => `Dyads picked: ${n} of 2`,
  curvePoint: 'Point on the centre-point curve',
  pickThis: 'Pick this dyad',
  clearPicks: 'Clear the dyads',
  burmesterPoints: (n) =>
    n === 0 ? 'No Burmester points: these poses have none.' : `${n} Burmester points (marked ◆ on the canvas).`,
  fourBarsTitle: 'Four-bars from the Burmester points',
  fourBarItem: (n, pairs) => `Four-bar ${n} (points ${pairs})`,
  approxDyads: (n) =>
    n === 0 ? 'No dyad fits these poses.' : `${n} best-fit dyads (marked ◆ and numbered on the canvas).`,
  approxFourBarsTitle: 'Four-bars from the best-fit dyads',
  approxItem: (n, pairs, rms) => `Four-bar ${n} (dyads ${pairs}): rms error ${rms}`,
  errorsTitle: 'Error at each pose',
  errorsCaption:
    'Where the coupler is when the crank points through each pose’s crank pin: distance and turn from the pose',
  columnPose: 'Pose',
  columnPositionError: 'position error',
  columnAngleError: 'angle error (°)',
  groundLength: 'Ground length |O2 O4|',
  groundAuto: (length) => `auto: ${length}`,
  timeRatio: 'Time ratio Q',
  poleNote: (x, y, rocker, swingDeg) =>
    `Pole (rocker pivot O4) at (${x}, ${y}); rocker length ${rocker}; swing ${swingDeg}°.`,
  rockersTitle: 'Crank pivots at that ground length',
  rockerItem: (n, mu) => `Crank pivot ${n}: smallest transmission angle ${mu}°`,
  designTitle: 'The linkage',
  links: (r1, r2, r3, r4) => `r1 = ${r1}, r2 = ${r2}, r3 = ${r3}, r4 = ${r4}`,
  typeLine: (type) => `Type: ${type}`,
  defectsTitle: 'Checks',
  defectWords: {
    order: 'Order defect: turning the crank one way does not reach the poses in the given order.',
    branch:
      'Branch defect: the poses are not all on one assembly branch, so the linkage must be taken apart to reach them.',
    'not-crank': 'Grashof check: the input cannot turn fully (it rocks), so it must be driven back and forth.',
  },
  defectShort: { order: 'order defect', branch: 'branch defect', 'not-crank': 'input rocks' },
  noDefectsShort: 'no defects',
  pivotsLine: (o2x, o2y, o4x, o4y) => `Fixed pivots: O2 (${o2x}, ${o2y}), O4 (${o4x}, ${o4y})`,
  noDefects: 'No order, branch or Grashof defect: the crank turns fully and reaches every pose in order on one branch.',
  shownAt: 'Show the linkage at',
  openInSimulator: 'Open in simulator',
  problems: {
    collinear: (pivot) =>
      `No circle passes through the three positions of ${pivot}: they lie on one line or two coincide. Move the pivot or a pose.`,
    coincident: 'Two pivots of this linkage coincide, so it has a link of zero length. Move a pivot.',
    degenerate:
      'These poses do not turn (or three are related by one rotation): Burmester theory needs poses that rotate.',
    noRotation: 'The two poses have the same direction: turn one, so that the body rotates about a pole.',
    halfTurn: 'The two poses differ by half a turn: a rocker swings less than 180°.',
    atPole: 'The pose point is the pole itself: move a pose so that the rocker has a length.',
    noCrankPivot: (ground, rocker) =>
      `No crank pivot lies at ground length ${ground} (rocker ${rocker}). Try a longer ground: for Q = 1 it must exceed the rocker.`,
    noApprox: 'No two best-fit dyads make a four-bar (their pivots coincide). Move a pose.',
    fewDyads: (found) =>
      `The best fit to these poses found ${found === 0 ? 'no dyad' : 'only one dyad'}, and a four-bar needs two different ones. Move or remove a pose that strays from the others' motion.`,
    noBurmester: 'These five poses have no Burmester points, so no four-bar reaches all five exactly. Move a pose.',
    pickTwo: (picked) => (picked === 0 ? 'Pick two dyads on the centre-point curve.' : 'Pick one more dyad.'),
  },
};
