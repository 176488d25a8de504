// `npm run test:loaded -- [npm test's arguments]`: `npm test` on a busy machine. The gate must pass when another
// build or another engineer shares the cores, not only on an idle one: a wait that needs the page to answer
// within a few hundred milliseconds passes here and flakes there. This runs the same suite (scripts/test.mjs,
// the same arguments and environment, its output as it is, its exit code) while a child process keeps one core
// busy with a spin loop (pure arithmetic, nothing allocated), so that such a wait fails here first.
// The spin loop cannot outlive the run: it is killed when test.mjs exits and when this process gets SIGINT,
// SIGTERM or SIGHUP (passed on to test.mjs), it stops by itself when this process is gone (its parent changes),
// and in any case after MAX_MINUTES.
import { spawn } from 'node:child_process';
import { join } from 'node:path';
import { root } from './setup.mjs';

/** The longest the spin loop runs, whatever happens to the run: several times the gate's budget (DEVELOPERS.md). */
const MAX_MINUTES = 90;

// Run by `node -e` (argv[1]: the deadline, ms since the epoch). Date.now() and the parent are checked every
// 10 million iterations (some milliseconds): nothing in between but integer arithmetic, whose result is used
// (the exit code's test) so that the loop is not dead code.
const SPIN = `
const deadline = Number(process.argv[1]);
const parent = process.ppid;
let x = 1;
for (;;) {
  for (let i = 0; i < 1e7; i++) x = (Math.imul(x, 1103515245) + 12345) | 0;
  if (Date.now() > deadline || process.ppid !== parent) process.exit(x === 0.5 ? 1 : 0);
}`;

const spinner = spawn(process.execPath, ['-e', SPIN, String(Date.now() + MAX_MINUTES * 60_000)], {
  stdio: 'ignore',
});
spinner.on('error', (error) => {
  console.error(`test:loaded: could not start the spin loop: ${error.message}`);
  for (const s of SIGNALS) process.off(s, forward);
  if (suite.exitCode === null && suite.signalCode === null) suite.kill('SIGTERM');
  process.exit(1);
});
console.log(
  `test:loaded: one core kept busy by a spin loop (pid ${spinner.pid}) for the whole run, at most ${MAX_MINUTES} min; running npm test`,
);

/** Stop the spin loop (nothing when it has stopped already). */
const stopSpinner = () => {
  if (spinner.exitCode === null && spinner.signalCode === null) spinner.kill('SIGTERM');
};

const suite = spawn(process.execPath, [join(root, 'scripts', 'test.mjs'), ...process.argv.slice(2)], {
  cwd: root,
  stdio: 'inherit',
});

/** @type {NodeJS.Signals[]} */
const SIGNALS = ['SIGINT', 'SIGTERM', 'SIGHUP'];
/** @param {NodeJS.Signals} signal */
const forward = (signal) => {
  stopSpinner();
  if (suite.exitCode === null && suite.signalCode === null) suite.kill(signal);
};
for (const signal of SIGNALS) process.on(signal, forward);

suite.on('error', (error) => {
  stopSpinner();
  console.error(`test:loaded: could not start scripts/test.mjs: ${error.message}`);
  process.exit(1);
});
suite.on('exit', (code, signal) => {
  stopSpinner();
  if (signal !== null) {
    // test.mjs died of the signal: so does this process (npm and the shell see the same cause).
    for (const s of SIGNALS) process.off(s, forward);
    process.kill(process.pid, signal);
    return;
  }
  process.exit(code ?? 1);
});
