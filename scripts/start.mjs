// `npm start`: install what is missing, build the packages, serve the playground on 127.0.0.1.
// Port: `npm start -- --port 5200`, or PORT=5200 npm start; default 5173 (Vite moves to the next free port when
// that one is taken, and prints the URL it serves).
// Vite runs as a child process; SIGINT, SIGTERM and SIGHUP sent to this process (Ctrl-C, `kill PID`, a CI job or
// process manager stopping it) are passed to Vite, and this process ends as Vite does, so the port is free once
// it has gone. A SIGTERM to the `npm start` process stops it too (see the parent watch below).
import { spawn } from 'node:child_process';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { buildPackages, ensureDependencies, root } from './setup.mjs';

const flag = process.argv.indexOf('--port');
const port = flag >= 0 ? process.argv[flag + 1] : (process.env.PORT ?? '5173');
if (!/^\d+$/.test(port ?? '') || Number(port) < 1 || Number(port) > 65535) {
  console.error(`shadelab: the port (--port or PORT) must be an integer from 1 to 65535; got ${port}`);
  process.exit(1);
}

ensureDependencies();
buildPackages();
const open = process.env.CI || (process.platform === 'linux' && !process.env.DISPLAY) ? [] : ['--open'];
// Vite's own script under this Node (not through npx, one more process that would have to pass signals on).
const vitePackage = createRequire(join(root, 'package.json')).resolve('vite/package.json');
const vite = spawn(
  process.execPath,
  [join(vitePackage, '..', 'bin', 'vite.js'), 'playground', '--host', '127.0.0.1', '--port', port, ...open],
  { cwd: root, stdio: 'inherit' },
);
/** @type {NodeJS.Signals[]} */
const SIGNALS = ['SIGINT', 'SIGTERM', 'SIGHUP'];
/** @param {NodeJS.Signals} signal */
const forward = (signal) => {
  if (vite.exitCode === null && vite.signalCode === null) vite.kill(signal);
};
for (const signal of SIGNALS) process.on(signal, forward);
// `npm start` runs this under `sh -c`, and npm passes a SIGTERM it receives to that shell only: the shell dies
// and leaves this process behind. A parent gone is a stop, as SIGTERM is.
const parent = process.ppid;
const watch = setInterval(() => {
  try {
    process.kill(parent, 0);
  } catch (error) {
    if (/** @type {NodeJS.ErrnoException} */ (error).code !== 'ESRCH') return;
    clearInterval(watch);
    forward('SIGTERM');
  }
}, 200);
vite.on('error', (error) => {
  console.error(`shadelab: could not start Vite: ${error.message}`);
  process.exit(1);
});
vite.on('exit', (code, signal) => {
  clearInterval(watch);
  if (signal !== null) {
    // Vite died of the signal: so does this process (the shell and npm see the same cause).
    for (const s of SIGNALS) process.off(s, forward);
    process.kill(process.pid, signal);
    return;
  }
  process.exit(code ?? 1);
});
