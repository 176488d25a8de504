// The pages Playwright serves: the playground, then the tests' harness pages (tests/harness/, at
// /harness/?page=<name>) beside it, in playground/dist-e2e-<port>. `npm test` runs this as a stage of its own, so
// that the build's time is measured apart from the tests', and sets SHADELAB_E2E_BUILT for Playwright, whose web
// server (playwright.config.ts) then serves this build instead of building again.
//
//   node scripts/e2e-build.mjs [--port N]    # default: $SHADELAB_E2E_PORT, else 4173
import { run } from './setup.mjs';

/** The build commands for `port`'s folder, in order. @param {number} port @returns {string[][]} */
export function e2eBuildCommands(port) {
  return [
    [
      'npx',
      'vite',
      'build',
      'playground',
      '--outDir',
      `dist-e2e-${port}`,
      '--emptyOutDir',
      '--logLevel',
      'warn',
    ],
    [
      'npx',
      'vite',
      'build',
      '--config',
      'tests/harness/vite.config.ts',
      '--outDir',
      `../playground/dist-e2e-${port}`,
      '--logLevel',
      'warn',
    ],
  ];
}

const at = process.argv.indexOf('--port');
const port = Number(at > 0 ? process.argv[at + 1] : (process.env.SHADELAB_E2E_PORT ?? 4173));
for (const [cmd, ...args] of e2eBuildCommands(port)) {
  const code = run(cmd, args);
  if (code !== 0) process.exit(code);
}
