// Size budget, minified and gzipped, without three (external). Two rows per package:
// - "core": what a typical app imports (the contract's main class), gated at the issue's targets;
// - "all": the whole public API (`export *`), gated at its own budget so growth is seen.
// `node scripts/size.mjs` checks the budgets; `--json PATH` also writes the numbers.
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { build } from 'vite';
import { root } from './setup.mjs';

/** @type {{ pkg: string, entry: string, exports: string[] | '*', budget: number }[]} */
const cases = [
  { pkg: 'sphere', entry: 'core', exports: ['SubdivisionSphereGeometry'], budget: 4096 },
  { pkg: 'sphere', entry: 'all', exports: '*', budget: 7168 },
  { pkg: 'camera', entry: 'core', exports: ['Camera'], budget: 4096 },
  { pkg: 'camera', entry: 'all', exports: '*', budget: 4608 },
  { pkg: 'trackball', entry: 'core', exports: ['Trackball'], budget: 4096 },
  { pkg: 'trackball', entry: 'all', exports: '*', budget: 4608 },
  { pkg: 'material', entry: 'core', exports: ['ShadingMaterial', 'PhongLight'], budget: 8192 },
  { pkg: 'material', entry: 'all', exports: '*', budget: 10240 },
  { pkg: 'reference', entry: 'core', exports: ['renderReference'], budget: 4096 },
  { pkg: 'reference', entry: 'all', exports: '*', budget: 4608 },
];

const tmp = join(root, 'node_modules', '.shadelab-size');
mkdirSync(tmp, { recursive: true });
const rows = [];
for (const c of cases) {
  const source = join(root, 'packages', c.pkg, 'src', 'index.ts');
  const entry = join(tmp, `${c.pkg}-${c.entry}.ts`);
  const names = c.exports === '*' ? '*' : `{ ${c.exports.join(', ')} }`;
  writeFileSync(entry, `export ${names} from ${JSON.stringify(source)};\n`);
  const result = await build({
    configFile: false,
    logLevel: 'silent',
    root,
    build: {
      write: false,
      minify: true,
      lib: { entry, formats: ['es'], fileName: c.pkg },
      rollupOptions: { external: (id) => id === 'three' || id.startsWith('three/') },
    },
  });
  const outputs = (Array.isArray(result) ? result : [result]).flatMap((r) => ('output' in r ? r.output : []));
  let minified = 0;
  let gzipped = 0;
  for (const chunk of outputs) {
    if (chunk.type !== 'chunk') continue;
    minified += Buffer.byteLength(chunk.code);
    gzipped += gzipSync(chunk.code, { level: 9 }).length;
  }
  rows.push({
    package: `@shadelab/${c.pkg}`,
    entry: c.exports === '*' ? 'whole API' : c.exports.join(' + '),
    minified,
    gzipped,
    budget: c.budget,
    ok: gzipped <= c.budget,
  });
}
rmSync(tmp, { recursive: true, force: true });

for (const r of rows) {
  console.log(
    `${r.ok ? 'ok  ' : 'OVER'} ${`${r.package} (${r.entry})`.padEnd(58)} ${String(r.minified).padStart(7)} B min  ${String(r.gzipped).padStart(6)} B gzip  (budget ${r.budget} B)`,
  );
}
const i = process.argv.indexOf('--json');
if (i >= 0) {
  mkdirSync(dirname(process.argv[i + 1]), { recursive: true });
  writeFileSync(process.argv[i + 1], `${JSON.stringify(rows, null, 2)}\n`);
}
process.exit(rows.every((r) => r.ok) ? 0 : 1);
