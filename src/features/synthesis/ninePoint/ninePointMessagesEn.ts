import type { NinePointMessages } from './ninePointMessages';

/** English strings of the Nine points mode. */
export const ninePointMessagesEn: NinePointMessages = {
  intro:
    'Place exactly nine target points: every four-bar whose coupler curve passes through all nine exactly is found ' +
    "(Alt's problem; nine is the most a four-bar can pass through), by tracking the 1442 paths of a polynomial " +
    'homotopy on your processor’s cores (Wampler, Morgan and Sommese 1992).',
  needNine: (count) => `Nine points needs exactly 9 target points; there ${count === 1 ? 'is' : 'are'} ${count}.`,
  refusalCoincide: (i, j, x, y) => `Points ${i} and ${j} coincide at (${x}, ${y}): nine distinct points are needed.`,
  refusalLine: 'The nine points lie on one line: every solution is at infinity. Move a point off the line.',
  refusalCircle: 'The nine points lie on one circle: every solution is at infinity. Move a point off the circle.',
  exampleProblem3: 'Example: Problem 3 (Wampler, Morgan, Sommese)',
  solve: 'Find every linkage',
  cancel: 'Cancel',
  progressLabel: 'Paths tracked',
  progressText: (done, total, roots, rootsTotal, real) =>
    `${done} of ${total} paths (${roots} of ${rootsTotal} roots) · ${real} real so far`,
  statusRunning: (workers) => `Tracking the paths on ${workers} worker${workers === 1 ? '' : 's'}…`,
  statusDone: (finished, total, roots, rootsTotal, failed, seconds, workers) =>
    `${finished} of ${total} paths (${roots} of ${rootsTotal} roots) finished in ${seconds} s on ${workers} ` +
    `worker${workers === 1 ? '' : 's'}` +
    (failed > 0 ? `; ${failed} path${failed === 1 ? '' : 's'} failed, so a class may be missing.` : '.'),
  statusCancelled: (tracked, total, roots, rootsTotal) =>
    `Cancelled after ${tracked} of ${total} paths (${roots} of ${rootsTotal} roots): the classes below are those ` +
    'found so far, not all.',
  statusFailed: (why) => `The run failed: ${why}`,
  statusRetracked: (n) =>
    ` ${n} path${n === 1 ? ' was' : 's were'} tracked again, carefully: two paths had ended at one solution.`,
  classCount: (classes, linkages) =>
    `${classes} real linkage class${classes === 1 ? '' : 'es'}, ${linkages} linkage${linkages === 1 ? '' : 's'}`,
  noClasses: 'No real linkage passes through these nine points.',
  classesTitle: 'Linkage classes',
  filtersLegend: 'Show only',
  filterGrashof: 'Grashof',
  filterCrank: 'Crank input',
  filterNoDefect: 'No circuit or order defect',
  maxSizeLabel: 'Longest link at most',
  maxSizeHelp: 'Empty: any size. A class fits when one of its cognates does.',
  maxSizeError: (text) => `Longest link at most: ${JSON.stringify(text)} is not a positive number.`,
  sortLabel: 'Sort by',
  sortText: { found: 'Order found', size: 'Smallest first', transmission: 'Best transmission angle' },
  shownCount: (shown, total) => `${shown} of ${total} classes shown`,
  noneMatch: 'No class matches these filters.',
  className: (n) => `Class ${n}`,
  longestLink: 'longest link',
  crankInput: 'crank input',
  noCrank: 'no crank',
  defectsLabel: 'Defects',
  noDefects: 'none',
  defectText: {
    circuit: 'circuit (the points lie on both circuits)',
    order: 'order (not met in order in one turn)',
    branch: 'branch (a dead centre between points)',
  },
  optimiserWorse: (distance) =>
    `The optimiser (Path mode) misses these nine points by up to ${distance}; every class here passes through all ` +
    'nine exactly.',
};
