import { bundleForNode } from './nodeBundle';
import { execFileSync } from 'node:child_process';
const b = await bundleForNode(new URL('./probe11.tmp.ts', import.meta.url).pathname);
console.log(execFileSync(process.execPath, [b.file], { encoding: 'utf8' }));
b.dispose();
