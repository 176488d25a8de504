import { defineConfig } from 'vite';
import { harnessConfig } from '../../tests/harness/vite.config.ts';

// The benchmarks' own harness pages (bench/harness/*.html, served at /harness/<name>.html): see
// tests/harness/vite.config.ts, whose config this is with bench/ as the root.
export default defineConfig(harnessConfig('bench'));
