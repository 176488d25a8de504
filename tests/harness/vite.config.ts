import { readdirSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { defineConfig, type UserConfig } from 'vite';

// The harness pages: bare pages that the Playwright tests (tests/harness/) and the benchmarks (bench/harness/)
// open, built apart from the playground. Each folder is built with its parent as Vite's root, so that its HTML
// files are served at /harness/<file>.html whichever folder holds them: the tests' one page at /harness/
// (index.html, which loads the module ?page= names: tests/harness/main.ts), each bench page at
// /harness/<name>.html.
//
//   npx vite build --config tests/harness/vite.config.ts --outDir DIR    # tests/harness/index.html
//   npx vite build --config bench/harness/vite.config.ts --outDir DIR    # bench/harness/*.html
//
// Both may write into one folder (and beside a playground build): the assets' names carry their content hash.
// The pages test the packages' sources: `@shadelab/x` resolves to packages/x/src/index.ts, a subpath
// `@shadelab/x/y` to src/y.ts.

const packages = ['sphere', 'camera', 'trackball', 'material', 'reference'];
const repo = fileURLToPath(new URL('../..', import.meta.url));

/** The Vite config that builds `<root>/harness/*.html` (root: `tests` or `bench`, from the repository). */
export function harnessConfig(root: string): UserConfig {
  const dir = join(repo, root);
  const pages = readdirSync(join(dir, 'harness'))
    .filter((f) => f.endsWith('.html'))
    .map((f) => [`harness/${f.slice(0, -5)}`, join(dir, 'harness', f)]);
  return {
    root: dir,
    publicDir: false,
    resolve: {
      alias: Object.fromEntries(
        packages.map((name) => [`@shadelab/${name}`, join(repo, 'packages', name, 'src')]),
      ),
      dedupe: ['three'],
    },
    build: {
      target: 'es2022',
      chunkSizeWarningLimit: 2000,
      // The output folder is a build's own (a temporary or dist-e2e-* folder), shared with other builds.
      emptyOutDir: false,
      rollupOptions: { input: Object.fromEntries(pages) },
    },
  };
}

export default defineConfig(harnessConfig('tests'));
