#!/usr/bin/env node
// The playground's bundle size: builds the app with its own Vite config (in memory, nothing written) and sums
// what index.html loads at start (its entry chunk and every chunk it imports statically) in three groups:
// three.js, React + react-dom + leva + the app, and the @shadelab packages' own chunks. Raw bytes and gzip -9.
//
//   node scripts/bundle-size.mjs                 # prints the README table
//   node scripts/bundle-size.mjs --json [file]   # also writes the figures (default bench/results/playground-bundle.json)
//
// Deterministic (no timing): the same sources give the same numbers on any machine.
import { sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import { build } from 'vite';
import { writeJson } from '../bench/lib/meta.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const args = process.argv.slice(2);
const jsonAt = args.indexOf('--json');
const jsonFile =
  jsonAt === -1
    ? null
    : args[jsonAt + 1] && !args[jsonAt + 1].startsWith('--')
      ? args[jsonAt + 1]
      : `${root}bench/results/playground-bundle.json`;

const result = await build({
  configFile: `${root}playground/vite.config.ts`,
  logLevel: 'warn',
  build: { write: false, emptyOutDir: false },
});
/** @typedef {import('vite').Rolldown.OutputChunk} Chunk */
const outputs = /** @type {import('vite').Rolldown.RolldownOutput[]} */ (
  Array.isArray(result) ? result : [result]
).flatMap((r) => r.output);
/** @type {Map<string, Chunk>} */
const chunks = new Map();
for (const o of outputs) if (o.type === 'chunk') chunks.set(o.fileName, o);

const entry = [...chunks.values()].find(
  (c) => c.isEntry && c.facadeModuleId?.endsWith(`${sep}playground${sep}index.html`),
);
if (!entry) throw new Error('bundle-size: no chunk for playground/index.html in the build');

/** The entry and every chunk it imports statically (what the page loads before its first frame). */
/** @type {Chunk[]} */
const loaded = [];
const seen = new Set();
const visit = (/** @type {string} */ fileName) => {
  if (seen.has(fileName)) return;
  seen.add(fileName);
  const chunk = chunks.get(fileName);
  if (!chunk) return;
  loaded.push(chunk);
  for (const imported of chunk.imports) visit(imported);
};
visit(entry.fileName);

const inThree = (/** @type {string} */ id) => /[\\/]node_modules[\\/]three[\\/]/.test(id);
const inPackages = (/** @type {string} */ id) =>
  id.startsWith(`${root}packages${sep}`) || id.startsWith(`${root}packages/`);

/**
 * A chunk's group: all of its modules from three, all from packages/, or otherwise the app's. The bundler's
 * own virtual helpers (ids starting with NUL: the module-preload polyfill, the runtime) do not decide it.
 */
function group(/** @type {Chunk} */ chunk) {
  const ids = Object.keys(chunk.modules).filter(
    (id) => !id.startsWith('\0') && chunk.modules[id].renderedLength > 0,
  );
  if (ids.length > 0 && ids.every(inThree)) return 'three';
  if (ids.length > 0 && ids.every(inPackages)) return 'shadelab';
  return 'app';
}

const LABELS = {
  three: 'three.js',
  app: 'React, react-dom, leva and the app',
  shadelab: 'the @shadelab packages (their own chunks)',
};
/** @type {Record<string, { raw: number, gzip: number, chunks: { file: string, raw: number, gzip: number }[] }>} */
const totals = Object.fromEntries(Object.keys(LABELS).map((k) => [k, { raw: 0, gzip: 0, chunks: [] }]));
for (const chunk of loaded) {
  const code = Buffer.from(chunk.code);
  const t = totals[group(chunk)];
  const gzip = gzipSync(code, { level: 9 }).length;
  t.raw += code.length;
  t.gzip += gzip;
  t.chunks.push({ file: chunk.fileName, raw: code.length, gzip });
}
const all = Object.values(totals).reduce((a, t) => ({ raw: a.raw + t.raw, gzip: a.gzip + t.gzip }), {
  raw: 0,
  gzip: 0,
});

const kB = (/** @type {number} */ n) =>
  `${(n / 1000).toLocaleString('en-US', { minimumFractionDigits: 1, maximumFractionDigits: 1 })} kB`;
const lines = [
  '| what `index.html` loads (`vite build`) | raw | gzip -9 |',
  '| --- | ---: | ---: |',
  ...Object.entries(LABELS).map(
    ([k, label]) => `| ${label} | ${kB(totals[k].raw)} | ${kB(totals[k].gzip)} |`,
  ),
  `| **total** | **${kB(all.raw)}** | **${kB(all.gzip)}** |`,
];
console.log(lines.join('\n'));
for (const [k, t] of Object.entries(totals)) {
  console.log(`  ${k}: ${t.chunks.map((c) => `${c.file} ${c.raw} B (${c.gzip} B gz)`).join(', ')}`);
}

if (jsonFile) {
  writeJson(jsonFile, {
    entry: 'playground/index.html',
    unit: 'bytes (kB = 1000 B in the table)',
    groups: totals,
    total: all,
  });
  console.log(`wrote ${jsonFile}`);
}
