// The repository's unit tests with `three` (and its examples) resolved to the release pinned in this folder,
// the oldest shadelab supports. Run through scripts/three-compat.mjs, from the repository root.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { configDefaults, defineConfig } from 'vitest/config';
import base from '../../vitest.config.ts';

const here = (path: string) => fileURLToPath(new URL(path, import.meta.url));
const three = here('./node_modules/three/');
const { version } = JSON.parse(readFileSync(`${three}package.json`, 'utf8')) as { version: string };

const packageAliases = Object.entries(base.resolve?.alias ?? {}).map(([find, replacement]) => ({
  find,
  replacement: replacement as string,
}));

export default defineConfig({
  root: here('../..'),
  resolve: {
    alias: [
      { find: /^three$/, replacement: `${three}build/three.module.js` },
      { find: /^three\/(examples\/jsm|addons)\/(.*)$/, replacement: `${three}examples/jsm/$2` },
      // React Three Fiber's ES module (its CommonJS build would require the root's three past the alias).
      {
        find: /^@react-three\/fiber$/,
        replacement: here('../../node_modules/@react-three/fiber/dist/react-three-fiber.esm.js'),
      },
      ...packageAliases,
    ],
  },
  define: { __THREE_COMPAT_VERSION__: JSON.stringify(version) },
  test: {
    ...base.test,
    // The repository's setup files (the fixed fast-check seed) and the check that the pinned three is used.
    setupFiles: [...[base.test?.setupFiles ?? []].flat(), here('./checkRevision.ts')],
    // The node materials (`@shadelab/material/webgpu`) need three ≥ 0.187: their tests import three/webgpu, which
    // has no pinned counterpart here (it would be the root's three beside the pinned one).
    // The repository's own tools (scripts/, bench/) never load three: their tests are the same code on any three.
    exclude: [
      ...(base.test?.exclude ?? configDefaults.exclude),
      'packages/*/src/**/*Node*.test.ts',
      'scripts/**',
      'bench/**',
    ],
    // React Three Fiber goes through the aliases too (its ES module, inlined), so that it and the packages share
    // the pinned three as they share one three in an app: left external, it loaded the root's three, and its
    // `instanceof THREE.Color` failed on the packages' colours (@shadelab/react's applyProps test).
    server: { deps: { inline: ['@react-three/fiber'] } },
  },
});
