import { type ChildProcess, spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import { delimiter, join } from 'node:path';

/** An X server started by {@link startXvfb}. */
export interface XvfbServer {
  /** Its display, such as `':99'`: the `DISPLAY` of the browsers it shows. */
  readonly display: string;
  /** Stops the server (SIGTERM), resolving when it has exited; idempotent. */
  stop(): Promise<void>;
}

/** Options of {@link startXvfb}. */
export interface XvfbOptions {
  /** The screen, `WIDTHxHEIGHTxDEPTH`. @default '1280x1024x24' */
  screen?: string;
  /** How long to wait for the server to report its display, in milliseconds. @default 10000 */
  timeout?: number;
  /** The Xvfb binary. @default the first `Xvfb` on `PATH` */
  executable?: string;
}

/** The first `Xvfb` on `PATH` (`env.PATH`), or null when there is none (Debian: `apt-get install xvfb`). */
export function findXvfb(env: Record<string, string | undefined> = process.env): string | null {
  for (const dir of (env.PATH ?? '').split(delimiter)) {
    if (dir === '') continue;
    const candidate = join(dir, 'Xvfb');
    if (existsSync(candidate)) return candidate;
  }
  return null;
}

/**
 * Start a virtual X server (Xvfb) on a free display, which it picks itself (`-displayfd`), so that a headed
 * Chromium has a screen: the llvmpipe mode of `shadelabPreset` draws WebGL with Mesa's llvmpipe there. Call
 * `stop()` when done (the kit's global setup does, see `XVFB_GLOBAL_SETUP`).
 *
 * @throws Error when no Xvfb is found (the message says how to install it) or it does not start in time.
 */
export async function startXvfb({
  screen = '1280x1024x24',
  timeout = 10_000,
  executable = findXvfb() ?? undefined,
}: XvfbOptions = {}): Promise<XvfbServer> {
  if (!/^\d+x\d+x\d+$/.test(screen)) {
    throw new RangeError(
      `startXvfb: screen must be WIDTHxHEIGHTxDEPTH such as '1280x1024x24', got ${screen}`,
    );
  }
  if (executable === undefined) {
    throw new Error(
      'startXvfb: no Xvfb on PATH. Install it (Debian/Ubuntu: apt-get install xvfb), or run the tests under xvfb-run.',
    );
  }
  const child: ChildProcess = spawn(
    executable,
    ['-displayfd', '3', '-screen', '0', screen, '-nolisten', 'tcp', '-noreset'],
    { stdio: ['ignore', 'ignore', 'pipe', 'pipe'] },
  );
  let stderr = '';
  child.stderr?.on('data', (chunk) => {
    stderr += String(chunk);
  });
  const exited = new Promise<void>((resolve) => child.once('exit', () => resolve()));
  const display = await new Promise<string>((resolve, reject) => {
    let out = '';
    const timer = setTimeout(() => {
      child.kill('SIGTERM');
      reject(new Error(`startXvfb: Xvfb reported no display within ${timeout} ms. ${stderr.trim()}`));
    }, timeout);
    const fd3 = child.stdio[3] as NodeJS.ReadableStream;
    fd3.on('data', (chunk) => {
      out += String(chunk);
      const line = out.match(/^(\d+)\n/);
      if (line) {
        clearTimeout(timer);
        resolve(`:${line[1]}`);
      }
    });
    child.once('error', (error) => {
      clearTimeout(timer);
      reject(new Error(`startXvfb: ${executable} could not be started: ${error.message}`));
    });
    child.once('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`startXvfb: Xvfb exited (code ${code}) before reporting a display. ${stderr.trim()}`));
    });
  });
  // A runner that exits without calling stop() (an uncaught error, a signal it handles) still ends its Xvfb.
  const onExit = () => {
    if (child.exitCode === null && child.signalCode === null) child.kill('SIGTERM');
  };
  process.once('exit', onExit);
  child.unref();
  (child.stdio[3] as NodeJS.ReadableStream & { unref?: () => void }).unref?.();
  (child.stderr as (NodeJS.ReadableStream & { unref?: () => void }) | null)?.unref?.();
  let stopped: Promise<void> | undefined;
  return {
    display,
    stop() {
      stopped ??= (async () => {
        process.removeListener('exit', onExit);
        // Referenced again while it exits: waiting on an unreferenced child alone would let Node's event loop
        // run empty and end the process with code 0 there (Playwright's runner, in a global teardown: its
        // summary unprinted and a failed run's exit code lost).
        child.ref();
        if (child.exitCode === null && child.signalCode === null) child.kill('SIGTERM');
        await exited;
      })();
      return stopped;
    },
  };
}
