import { sweep, theta2Grid } from '../src/solver';
const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
const g = theta2Grid(0, 360, 1);
let s = 0;
for (let round = 0; round < 20000; round++) s += sweep(l, g, { branch: 'open', method: 'newton' }).totalIterations;
console.log(s);
