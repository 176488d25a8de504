// Which Chromium Playwright launches. Order: $SHADELAB_CHROMIUM, Debian's /usr/bin/chromium,
// then Playwright's own browser (`npx playwright install chromium` on a laptop).
import { existsSync } from 'node:fs';
import { createRequire } from 'node:module';

const DEBIAN = '/usr/bin/chromium';

/** @returns {string | undefined | null} a path, undefined for Playwright's own browser, null for none. */
export function chromiumExecutable() {
  const named = process.env.SHADELAB_CHROMIUM;
  if (named) return existsSync(named) ? named : null;
  if (existsSync(DEBIAN)) return DEBIAN;
  try {
    const require = createRequire(import.meta.url);
    const { chromium } = require('playwright-core');
    if (existsSync(chromium.executablePath())) return undefined;
  } catch {
    // playwright-core not installed yet, or no browser registry: fall through.
  }
  return null;
}

export function describeBrowserSearch() {
  return `Looked at $SHADELAB_CHROMIUM, ${DEBIAN} and Playwright's own browsers. Install one (apt-get install chromium, or npx playwright install chromium) or set SHADELAB_CHROMIUM to a Chromium binary.`;
}

/** Flags every Playwright run uses, so that baselines and tests render the same (SwiftShader WebGL2). */
export const chromiumArgs = [
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--no-first-run',
];
