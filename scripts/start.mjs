// `npm start`: install what is missing, build the packages, serve the playground on 127.0.0.1.
// Port: `npm start -- --port 5200`, or PORT=5200 npm start; default 5173 (Vite moves to the next free port when
// that one is taken, and prints the URL it serves).
import { buildPackages, ensureDependencies, run } from './setup.mjs';

const flag = process.argv.indexOf('--port');
const port = flag >= 0 ? process.argv[flag + 1] : (process.env.PORT ?? '5173');
if (!/^\d+$/.test(port ?? '') || Number(port) < 1 || Number(port) > 65535) {
  console.error(`shadelab: the port (--port or PORT) must be an integer from 1 to 65535; got ${port}`);
  process.exit(1);
}

ensureDependencies();
buildPackages();
const open = process.env.CI || (process.platform === 'linux' && !process.env.DISPLAY) ? [] : ['--open'];
process.exit(run('npx', ['vite', 'playground', '--host', '127.0.0.1', '--port', port, ...open]));
