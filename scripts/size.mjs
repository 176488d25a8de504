// Size budget: each package's whole public API bundled, minified and gzipped, without three.
// `node scripts/size.mjs` checks the budgets; `--json PATH` also writes the numbers.
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { build } from 'vite';
import { root } from './setup.mjs';

/** Budgets in bytes, minified + gzipped. */
const budgets = { sphere: 4096, camera: 4096, trackball: 4096, material: 8192, reference: 8192 };

const rows = [];
for (const [name, budget] of Object.entries(budgets)) {
  const result = await build({
    configFile: false,
    logLevel: 'silent',
    root,
    build: {
      write: false,
      minify: true,
      lib: { entry: join(root, 'packages', name, 'src', 'index.ts'), formats: ['es'], fileName: name },
      rollupOptions: {
        external: (id) => id === 'three' || id.startsWith('three/') || id.startsWith('@shadelab/'),
      },
    },
  });
  const outputs = (Array.isArray(result) ? result : [result]).flatMap((r) => ('output' in r ? r.output : []));
  let min = 0;
  let gz = 0;
  for (const chunk of outputs) {
    if (chunk.type !== 'chunk') continue;
    min += Buffer.byteLength(chunk.code);
    gz += gzipSync(chunk.code, { level: 9 }).length;
  }
  rows.push({ package: `@shadelab/${name}`, minified: min, gzipped: gz, budget, ok: gz <= budget });
}

for (const r of rows) {
  console.log(
    `${r.ok ? 'ok  ' : 'OVER'} ${r.package.padEnd(20)} ${String(r.minified).padStart(7)} B min  ${String(r.gzipped).padStart(6)} B gzip  (budget ${r.budget} B)`,
  );
}
const i = process.argv.indexOf('--json');
if (i >= 0) {
  mkdirSync(dirname(process.argv[i + 1]), { recursive: true });
  writeFileSync(process.argv[i + 1], `${JSON.stringify(rows, null, 2)}\n`);
}
process.exit(rows.every((r) => r.ok) ? 0 : 1);
