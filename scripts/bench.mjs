// `npm run bench`: build the packages, then run every bench/*.bench.mjs (or the ones named) and
// write their results to bench/results/<name>.json.
import { readdirSync } from 'node:fs';
import { join } from 'node:path';
import { buildPackages, ensureBrowser, ensureDependencies, root, run } from './setup.mjs';

ensureDependencies();
await ensureBrowser();
buildPackages();
const only = process.argv.slice(2);
const benches = readdirSync(join(root, 'bench'))
  .filter((f) => f.endsWith('.bench.mjs'))
  .filter((f) => only.length === 0 || only.some((o) => f.startsWith(o)));
let failed = 0;
for (const file of benches) {
  const name = file.replace(/\.bench\.mjs$/, '');
  console.log(`\n── bench ${name} ──`);
  if (run('node', [join('bench', file), '--json', join('bench', 'results', `${name}.json`)]) !== 0) failed++;
}
process.exit(failed ? 1 : 0);
