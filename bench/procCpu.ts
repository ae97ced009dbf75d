/**
 * CPU time of Chromium's processes and threads from /proc (Linux only), robust to a loaded machine in a way frames per
 * second are not: for bench:ui's Spatial rows and bench/spatialProbe.ts.
 */
import { readFileSync, readdirSync } from 'node:fs';

const CLK_TCK = 100;

/** utime + stime (ms) of a /proc stat line's fields after the command, 0 when unreadable. */
function statCpuMs(path: string): number {
  try {
    const stat = readFileSync(path, 'utf8');
    const f = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
    return ((Number(f[11]) + Number(f[12])) * 1000) / CLK_TCK;
  } catch {
    return 0;
  }
}

/** utime + stime (ms) of a process, 0 when it is gone. */
export function cpuMs(pid: number): number {
  return statCpuMs(`/proc/${pid}/stat`);
}

/** utime + stime (ms) of a process's main thread (a renderer's page thread), 0 when it is gone. */
export function mainThreadCpuMs(pid: number): number {
  return statCpuMs(`/proc/${pid}/task/${pid}/stat`);
}

/**
 * utime + stime (ms) summed over a process's threads whose name (comm) matches: Chromium names a dedicated worker's
 * thread "DedicatedWorker thread" (comm "DedicatedWorker"), so /^DedicatedWorker/ is the page's workers' own CPU.
 */
export function threadsCpuMs(pid: number, name: RegExp): number {
  let total = 0;
  let tids: string[] = [];
  try {
    tids = readdirSync(`/proc/${pid}/task`);
  } catch {
    return 0;
  }
  for (const tid of tids) {
    let comm = '';
    try {
      comm = readFileSync(`/proc/${pid}/task/${tid}/comm`, 'utf8').trim();
    } catch {
      continue;
    }
    if (name.test(comm)) total += statCpuMs(`/proc/${pid}/task/${tid}/stat`);
  }
  return total;
}

/** The descendants of this process by their Chromium --type (gpu-process, renderer, ...; 'browser' without one). */
export function chromiumProcesses(): Map<string, number[]> {
  const parent = new Map<number, number>();
  for (const name of readdirSync('/proc')) {
    if (!/^\d+$/.test(name)) continue;
    try {
      const stat = readFileSync(`/proc/${name}/stat`, 'utf8');
      parent.set(Number(name), Number(stat.slice(stat.lastIndexOf(')') + 2).split(' ')[1]));
    } catch {
      /* gone */
    }
  }
  const mine = (pid: number): boolean => {
    for (let p = pid, n = 0; p > 1 && n < 50; p = parent.get(p) ?? 0, n++) if (p === process.pid) return true;
    return false;
  };
  const out = new Map<string, number[]>();
  for (const pid of parent.keys()) {
    if (pid === process.pid || !mine(pid)) continue;
    let cmd = '';
    try {
      cmd = readFileSync(`/proc/${pid}/cmdline`, 'utf8');
    } catch {
      continue;
    }
    const type = /--type=([\w-]+)/.exec(cmd)?.[1] ?? 'browser';
    out.set(type, [...(out.get(type) ?? []), pid]);
  }
  return out;
}

/** CPU ms now of Chromium's GPU process, its renderers, and the renderers' dedicated worker threads. */
export function chromiumCpu(): { gpu: number; renderer: number; workers: number } {
  const procs = chromiumProcesses();
  const sum = (type: string, f: (pid: number) => number) => (procs.get(type) ?? []).reduce((s, pid) => s + f(pid), 0);
  return {
    gpu: sum('gpu-process', cpuMs),
    renderer: sum('renderer', cpuMs),
    workers: sum('renderer', (pid) => threadsCpuMs(pid, /^DedicatedWorker/)),
  };
}
