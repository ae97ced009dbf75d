/**
 * One part of a path synthesis's global stage, run bundled in a child node process (bench/synthesisPool.ts), as one
 * worker of the synthesis page's pool runs it: args <task as JSON> <seed> <part> <parts> <rounds>. Prints one JSON
 * line: the part's candidates, rounds and evaluations.
 */
import { pathSynthesisPart } from '../src/synthesis';
import type { PathTask } from '../src/synthesis';

const [taskJson, seed, part, parts, rounds] = process.argv.slice(2);
const task = JSON.parse(taskJson) as PathTask;
const result = await pathSynthesisPart(task, {
  seed: Number(seed),
  part: Number(part),
  parts: Number(parts),
  rounds: Number(rounds),
  budgetMs: 600_000,
});
console.log(JSON.stringify(result));
