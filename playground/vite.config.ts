import { readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import react from '@vitejs/plugin-react';
import { defineConfig } from 'vite';

// The playground edits the packages live: resolve them to their TypeScript sources (`@shadelab/x` to
// src/index.ts, a subpath `@shadelab/x/y` to src/y.ts).
const src = (name: string) => fileURLToPath(new URL(`../packages/${name}/src`, import.meta.url));

const here = (path: string) => fileURLToPath(new URL(path, import.meta.url));

// Every top-level page (index.html, tradeoff.html, …) is an entry of the app.
const pages = Object.fromEntries(
  readdirSync(here('.'))
    .filter((f) => f.endsWith('.html'))
    .map((f) => [f === 'index.html' ? 'main' : f.slice(0, -5), here(`./${f}`)]),
);

export default defineConfig({
  root: fileURLToPath(new URL('.', import.meta.url)),
  plugins: [react()],
  resolve: {
    alias: {
      '@shadelab/sphere': src('sphere'),
      '@shadelab/camera': src('camera'),
      '@shadelab/trackball': src('trackball'),
      '@shadelab/material': src('material'),
      '@shadelab/reference': src('reference'),
    },
    dedupe: ['three', 'react', 'react-dom'],
  },
  build: {
    target: 'es2022',
    chunkSizeWarningLimit: 2000,
    rollupOptions: { input: pages },
  },
});
