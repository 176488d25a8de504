import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';

// Each package resolves to its source folder: `@shadelab/x` to src/index.ts, a subpath `@shadelab/x/y` to src/y.ts.
const src = (name: string) => fileURLToPath(new URL(`./packages/${name}/src`, import.meta.url));

export default defineConfig({
  resolve: {
    alias: {
      '@shadelab/sphere': src('sphere'),
      '@shadelab/camera': src('camera'),
      '@shadelab/trackball': src('trackball'),
      '@shadelab/material': src('material'),
      '@shadelab/reference': src('reference'),
      '@shadelab/playwright': src('playwright'),
      '@shadelab/react': src('react'),
    },
  },
  test: {
    include: [
      'packages/*/src/**/*.test.ts',
      'playground/src/**/*.test.ts',
      'bench/**/*.test.ts',
      'scripts/**/*.test.ts',
    ],
    environment: 'node',
    testTimeout: 60_000,
    // One module graph per worker, not one per file: three, the packages and fast-check are imported once. No test
    // file relies on a fresh graph: each makes its own scenes and materials, restores its spies, and vi.mock stays
    // within its file.
    isolate: false,
    // Every fast-check property runs from one fixed seed (SHADELAB_FUZZ_SEED overrides it; see npm run fuzz).
    setupFiles: [fileURLToPath(new URL('./test-utils/fastCheckSeed.ts', import.meta.url))],
  },
});
