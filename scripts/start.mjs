// `npm start`: install what is missing, build the packages, serve the playground on 127.0.0.1.
import { buildPackages, ensureDependencies, run } from './setup.mjs';

ensureDependencies();
buildPackages();
const open = process.env.CI || (process.platform === 'linux' && !process.env.DISPLAY) ? [] : ['--open'];
process.exit(
  run('npx', ['vite', 'playground', '--host', '127.0.0.1', '--port', process.env.PORT ?? '5173', ...open]),
);
