import { fileURLToPath } from 'node:url';
import react from '@vitejs/plugin-react';
import { defineConfig } from 'vite';

// The playground edits the packages live: resolve them to their TypeScript sources.
const src = (name: string) => fileURLToPath(new URL(`../packages/${name}/src/index.ts`, import.meta.url));

export default defineConfig({
  root: fileURLToPath(new URL('.', import.meta.url)),
  plugins: [react()],
  resolve: {
    alias: {
      '@shadelab/sphere': src('sphere'),
      '@shadelab/camera': src('camera'),
      '@shadelab/trackball': src('trackball'),
      '@shadelab/material': src('material'),
    },
    dedupe: ['three', 'react', 'react-dom'],
  },
  build: { target: 'es2022', chunkSizeWarningLimit: 2000 },
});
