#!/usr/bin/env node
// The playground's bundle size: builds the app with its own Vite config (in memory, nothing written) and sums
// what index.html loads at start (its entry chunk and every chunk it imports statically) in three groups:
// three.js, React + react-dom + leva + the app, and the @shadelab packages' own chunks. Raw bytes and gzip -9.
//
//   node scripts/bundle-size.mjs                 # prints the README table
//   node scripts/bundle-size.mjs --json [file]   # also writes the figures (default bench/results/playground-bundle.json)
//
// Deterministic (no timing): the same sources give the same numbers on any machine.
import { fileURLToPath } from 'node:url';
import { build } from 'vite';
import { BUNDLE_GROUPS, indexBundle } from '../bench/lib/bundle.mjs';
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
const { groups: totals, total: all } = indexBundle(result, root);
const LABELS = BUNDLE_GROUPS;

const kB = (/** @type {number} */ n) =>
  `${(n / 1000).toLocaleString('en-US', { minimumFractionDigits: 1, maximumFractionDigits: 1 })} kB`;
const lines = [
  '| what `index.html` loads (`vite build`) | raw | gzip -9 |',
  '| --- | ---: | ---: |',
  ...Object.entries(totals).map(
    ([k, t]) => `| ${LABELS[/** @type {keyof typeof LABELS} */ (k)]} | ${kB(t.raw)} | ${kB(t.gzip)} |`,
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
