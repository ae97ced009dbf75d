// Module scripts run after the document is parsed even when inline, so the script can stay in <head>.
// Replacements use functions: the code contains "$&"-like sequences that a replacement string would expand.
// Post-build step of `npm run build:single`: puts the one script and the one stylesheet that
// vite.single.config.ts wrote into dist-single/index.html, and the favicon as a data URL, giving
// dist-single/fourbar-lab.html, a file that needs nothing else (file://, a Moodle file resource).
import { readFileSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const out = join(root, 'dist-single');
let html = readFileSync(join(out, 'index.html'), 'utf8');

/** Replaces the one tag that matches re, failing the build when there is not exactly one. */
function replaceOne(re, make) {
  const hits = html.match(new RegExp(re.source, 'g')) ?? [];
  if (hits.length !== 1) throw new Error(`inline-single: expected one ${re} in index.html, found ${hits.length}`);
  html = html.replace(re, (...m) => make(...m));
}

const script = /<script type="module" crossorigin src="\.\/(assets\/[^"]+\.js)"><\/script>/;
const style = /<link rel="stylesheet" crossorigin href="\.\/(assets\/[^"]+\.css)">/;
replaceOne(script, (_, file) => {
  const js = readFileSync(join(out, file), 'utf8');
  // Inside <script>, only "</script" (any case) and "<!--" can end or confuse the element.
  if (/<!--/.test(js)) throw new Error('inline-single: the script contains "<!--"; it cannot be inlined as is');
  return `<script type="module">${js.replace(/<\/(script)/gi, '<\\/$1')}</script>`;
});
replaceOne(style, (_, file) => {
  const css = readFileSync(join(out, file), 'utf8');
  return `<style>${css.replace(/<\/(style)/gi, '<\\/$1')}</style>`;
});
replaceOne(/<link rel="icon" href="\.\/favicon\.svg" type="image\/svg\+xml" \/>/, () => {
  const svg = readFileSync(join(root, 'public', 'favicon.svg'));
  return `<link rel="icon" href="data:image/svg+xml;base64,${svg.toString('base64')}" type="image/svg+xml" />`;
});

writeFileSync(join(out, 'fourbar-lab.html'), html);
rmSync(join(out, 'index.html'));
rmSync(join(out, 'assets'), { recursive: true });
console.log(`dist-single/fourbar-lab.html: ${(Buffer.byteLength(html) / 1024).toFixed(1)} KiB`);
