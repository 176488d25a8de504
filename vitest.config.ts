import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';

const src = (name: string) => fileURLToPath(new URL(`./packages/${name}/src/index.ts`, import.meta.url));

export default defineConfig({
  resolve: {
    alias: {
      '@shadelab/sphere': src('sphere'),
      '@shadelab/camera': src('camera'),
      '@shadelab/trackball': src('trackball'),
      '@shadelab/material': src('material'),
      '@shadelab/reference': src('reference'),
    },
  },
  test: {
    include: ['packages/*/src/**/*.test.ts', 'playground/src/**/*.test.ts', 'bench/**/*.test.ts'],
    environment: 'node',
    testTimeout: 60_000,
  },
});
