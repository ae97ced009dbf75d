/**
 * Runs a bench script as the app ships it: bundled by vite into one plain ES module and executed by
 * node in a child process. Timing under vite-node would charge the solver for its module transform
 * (every imported binding becomes a property read on a module object), which no build pays, while the
 * lean yardstick (bench/leanReport.ts) imports nothing and would not pay it.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { build } from 'vite';

/** A bundled script ready to run, and how to remove it. */
export interface NodeBundle {
  file: string;
  dispose(): void;
}

/** Bundles entry (a .ts path) for node into a temporary directory. */
export async function bundleForNode(entry: string): Promise<NodeBundle> {
  const dir = mkdtempSync(join(tmpdir(), 'fourbar-bench-'));
  await build({
    configFile: false,
    logLevel: 'silent',
    build: {
      ssr: entry,
      outDir: dir,
      emptyOutDir: true,
      minify: false,
      target: 'node20',
      rollupOptions: { output: { format: 'es', entryFileNames: 'bench.mjs' } },
    },
  });
  return { file: join(dir, 'bench.mjs'), dispose: () => rmSync(dir, { recursive: true, force: true }) };
}

/** Runs the bundle with args in a fresh node process and parses the JSON line it prints last. */
export function runBundle<T>(bundle: NodeBundle, args: string[], nodeFlags: string[] = []): T {
  const out = execFileSync(process.execPath, [...nodeFlags, bundle.file, ...args], {
    encoding: 'utf8',
    maxBuffer: 64 * 1024 * 1024,
  });
  const lines = out.trim().split('\n');
  return JSON.parse(lines[lines.length - 1]) as T;
}
