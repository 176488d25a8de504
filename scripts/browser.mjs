// Which Chromium Playwright launches. Order: $SHADELAB_CHROMIUM, Debian's /usr/bin/chromium,
// then Playwright's own browser (`npx playwright install chromium` on a laptop).
import { existsSync } from 'node:fs';
import { createRequire } from 'node:module';

export const DEBIAN_CHROMIUM = '/usr/bin/chromium';

/** Where Playwright's own Chromium would be, or undefined when playwright-core is not installed yet. */
function playwrightChromiumPath() {
  try {
    const require = createRequire(import.meta.url);
    const { chromium } = require('playwright-core');
    return chromium.executablePath();
  } catch {
    // playwright-core not installed yet, or no browser registry.
    return undefined;
  }
}

/**
 * @typedef {object} ChromiumLookup
 * @property {string | undefined | null} executable a path; undefined for Playwright's own browser; null for none.
 * @property {'SHADELAB_CHROMIUM' | 'debian' | 'playwright' | 'none'} source where it was found ('none': nowhere).
 * @property {string[]} searched what was looked at, in order, for messages.
 * @property {string} [problem] set when SHADELAB_CHROMIUM names a file that does not exist (nothing else is tried).
 */

/**
 * Find the Chromium for Playwright. The checks are parameters so that tests can fake them.
 * @param {{ env?: Record<string, string | undefined>, exists?: (path: string) => boolean,
 *   playwrightPath?: () => string | undefined }} [checks]
 * @returns {ChromiumLookup}
 */
export function lookupChromium({
  env = process.env,
  exists = existsSync,
  playwrightPath = playwrightChromiumPath,
} = {}) {
  const named = env.SHADELAB_CHROMIUM;
  if (named) {
    const searched = [`$SHADELAB_CHROMIUM (${named})`];
    if (exists(named)) return { executable: named, source: 'SHADELAB_CHROMIUM', searched };
    return {
      executable: null,
      source: 'none',
      searched,
      problem: `SHADELAB_CHROMIUM is set to ${named}, which does not exist: point it at a Chromium binary, or unset it to use ${DEBIAN_CHROMIUM} or Playwright's own browser.`,
    };
  }
  const searched = ['$SHADELAB_CHROMIUM (not set)', DEBIAN_CHROMIUM];
  if (exists(DEBIAN_CHROMIUM)) return { executable: DEBIAN_CHROMIUM, source: 'debian', searched };
  const own = playwrightPath();
  searched.push(
    own ? `Playwright's own browser (${own})` : "Playwright's own browser (playwright-core not installed)",
  );
  if (own && exists(own)) return { executable: undefined, source: 'playwright', searched };
  return { executable: null, source: 'none', searched };
}

/** @returns {string | undefined | null} a path, undefined for Playwright's own browser, null for none. */
export function chromiumExecutable() {
  return lookupChromium().executable;
}

/** @param {ChromiumLookup} [lookup] */
export function describeBrowserSearch(lookup = lookupChromium()) {
  return `Looked at ${lookup.searched.join(', ')}. Install one (apt-get install chromium, or npx playwright install chromium) or set SHADELAB_CHROMIUM to a Chromium binary.`;
}

/** Flags every Playwright run uses, so that baselines and tests render the same (SwiftShader WebGL2). */
export const chromiumArgs = [
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--no-first-run',
];
