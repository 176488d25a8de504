import { spawnSync } from 'node:child_process';
import { statSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { findXvfb, startXvfb } from './xvfb.js';
import xvfbGlobalSetup, { XVFB_DISPLAY_ENV } from './xvfbGlobalSetup.js';

/**
 * The inode of `display`'s X socket (Xvfb makes it when it starts and removes it when it stops), or null when there
 * is none. Another Xvfb may take a display as soon as it is freed (the gate runs the unit stages and Playwright's
 * global setup at once): its socket is a new one.
 */
function socketOf(display: string): number | null {
  try {
    const socket = statSync(`/tmp/.X11-unix/X${display.slice(1)}`);
    return socket.isSocket() ? socket.ino : null;
  } catch {
    return null;
  }
}

describe('startXvfb', () => {
  it('starts an X server on a display it picks, which stop() ends', async () => {
    // `npm test` installs Debian's xvfb as it installs chromium (scripts/setup.mjs).
    expect(findXvfb()).not.toBeNull();
    const server = await startXvfb();
    expect(server.display).toMatch(/^:\d+$/);
    const socket = socketOf(server.display);
    expect(socket).not.toBeNull();
    await server.stop();
    await server.stop(); // idempotent
    expect(socketOf(server.display), "the server's socket is gone").not.toBe(socket);
  });

  it("keeps the process alive while stop() waits (regression: a runner with nothing else pending exited there with code 0, its failed run's exit code lost)", () => {
    // A process whose only pending work is stop(): it must go on after it and end with its own exit code.
    const script = [
      `import { startXvfb } from ${JSON.stringify(new URL('../dist/xvfb.js', import.meta.url).href)};`,
      'const server = await startXvfb();',
      'await server.stop();',
      "console.log('after stop');",
      'process.exitCode = 3;',
    ].join('\n');
    const run = spawnSync(process.execPath, ['--input-type=module', '-e', script], { encoding: 'utf8' });
    expect(run.stderr).toBe('');
    expect(run.stdout).toBe('after stop\n');
    expect(run.status).toBe(3);
  });

  it('finds none on a PATH without it, says when the binary cannot start, and refuses a bad screen', async () => {
    expect(findXvfb({ PATH: '/nonexistent' })).toBeNull();
    await expect(startXvfb({ screen: 'big' })).rejects.toThrow(
      new RangeError("startXvfb: screen must be WIDTHxHEIGHTxDEPTH such as '1280x1024x24', got big"),
    );
    await expect(startXvfb({ executable: '/nonexistent/Xvfb' })).rejects.toThrow(
      'startXvfb: /nonexistent/Xvfb could not be started',
    );
  });
});

describe('the global setup', () => {
  it('starts Xvfb only for a config with an llvmpipe project, hands its display to the workers and stops it', async () => {
    const llvmpipe = { use: { launchOptions: { env: { SHADELAB_RASTERISER: 'llvmpipe' } } } };
    expect(await xvfbGlobalSetup({ projects: [{ use: {} }] } as never)).toBeUndefined();
    expect(process.env[XVFB_DISPLAY_ENV]).toBeUndefined();
    const teardown = await xvfbGlobalSetup({ projects: [{ use: {} }, llvmpipe] } as never);
    const display = process.env[XVFB_DISPLAY_ENV] as string;
    expect(display).toMatch(/^:\d+$/);
    const socket = socketOf(display);
    expect(socket).not.toBeNull();
    await teardown?.();
    expect(process.env[XVFB_DISPLAY_ENV]).toBeUndefined();
    expect(socketOf(display), "the server's socket is gone").not.toBe(socket);
  });
});
