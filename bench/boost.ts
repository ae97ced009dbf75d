/**
 * BENCH_BOOST=1: keeps this process and every process it starts (the browser, its zygote, renderers and GPU
 * process) in Linux autogroups at the highest weight, so a benchmark on a machine shared with other work measures
 * the app, not the queue. Plain `nice` does not reach across sessions: the scheduler first shares the CPU between
 * autogroups, and Chromium's zygote starts new sessions, so each new process's /proc/<pid>/autogroup is set as it
 * appears (checked every 250 ms). Needs the right to raise priority (root); otherwise it does nothing.
 */
import { readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { setPriority } from 'node:os';

/** The parent pid of each process, from /proc. */
function parents(): Map<number, number> {
  const out = new Map<number, number>();
  for (const name of readdirSync('/proc')) {
    if (!/^\d+$/.test(name)) continue;
    try {
      const stat = readFileSync(`/proc/${name}/stat`, 'utf8');
      const ppid = Number(stat.slice(stat.lastIndexOf(')') + 2).split(' ')[1]);
      out.set(Number(name), ppid);
    } catch {
      // The process ended while being read.
    }
  }
  return out;
}

/** This process and its descendants. */
function family(): number[] {
  const byParent = parents();
  const mine = new Set([process.pid]);
  for (let grew = true; grew;) {
    grew = false;
    for (const [pid, ppid] of byParent)
      if (mine.has(ppid) && !mine.has(pid)) {
        mine.add(pid);
        grew = true;
      }
  }
  return [...mine];
}

/** Starts boosting when BENCH_BOOST is set; returns the function that stops it. */
export function startBoost(): () => void {
  if (!process.env.BENCH_BOOST || process.platform !== 'linux') return () => {};
  const done = new Set<number>();
  const boost = () => {
    for (const pid of family()) {
      if (done.has(pid)) continue;
      done.add(pid);
      try {
        writeFileSync(`/proc/${pid}/autogroup`, '-20');
        setPriority(pid, -20);
      } catch {
        // Not permitted or already gone: measure unboosted.
      }
    }
  };
  boost();
  const timer = setInterval(boost, 250);
  return () => clearInterval(timer);
}
