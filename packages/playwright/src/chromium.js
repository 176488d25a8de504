// Which Chromium Playwright launches, and the flags that make its pictures the same on every machine. Plain
// JavaScript (type-checked from its JSDoc) so that a set-up script can import this source before anything is
// built: the repository's scripts/browser.mjs re-exports it for `npm test`'s browser check.
import { existsSync } from 'node:fs';
import { createRequire } from 'node:module';

/** Debian's (and Ubuntu's snap wrapper's) Chromium, the second place {@link lookupChromium} looks. */
export const DEBIAN_CHROMIUM = '/usr/bin/chromium';

/**
 * Where Playwright's own Chromium would be (`npx playwright install chromium` puts it there), or undefined when
 * neither playwright-core nor @playwright/test can be loaded from here.
 * @returns {string | undefined}
 */
function playwrightChromiumPath() {
  const require = createRequire(import.meta.url);
  for (const name of ['playwright-core', '@playwright/test']) {
    try {
      return require(name).chromium.executablePath();
    } catch {
      // Not installed here, or no browser registry: try the next one.
    }
  }
  return undefined;
}

/**
 * What {@link lookupChromium} found.
 * @typedef {object} ChromiumLookup
 * @property {string | undefined | null} executable A path to launch; undefined for Playwright's own browser
 *   (Playwright finds it); null when there is none.
 * @property {'SHADELAB_CHROMIUM' | 'debian' | 'playwright' | 'none'} source Where it was found ('none': nowhere).
 * @property {string[]} searched What was looked at, in order, for messages.
 * @property {string} [problem] Set when SHADELAB_CHROMIUM names a file that does not exist (nothing else is
 *   tried then).
 */

/**
 * The checks {@link lookupChromium} makes, as parameters so that tests can fake them.
 * @typedef {object} ChromiumChecks
 * @property {Record<string, string | undefined>} [env] The environment. Default: `process.env`.
 * @property {(path: string) => boolean} [exists] Whether a file exists. Default: `fs.existsSync`.
 * @property {() => string | undefined} [playwrightPath] Where Playwright's own Chromium would be, or undefined
 *   when Playwright is not installed. Default: `chromium.executablePath()` of playwright-core.
 */

/**
 * Find the Chromium for Playwright. Order: `$SHADELAB_CHROMIUM` (when set it must exist: nothing else is
 * tried), Debian's `/usr/bin/chromium`, then Playwright's own browser.
 * @param {ChromiumChecks} [checks]
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

/**
 * The Chromium to launch: a path, undefined for Playwright's own browser, null for none.
 * @returns {string | undefined | null}
 */
export function chromiumExecutable() {
  return lookupChromium().executable;
}

/**
 * What was searched and how to get a browser, for an error message.
 * @param {ChromiumLookup} [lookup] A lookup's result. Default: a new {@link lookupChromium}.
 * @returns {string}
 */
export function describeBrowserSearch(lookup = lookupChromium()) {
  return `Looked at ${lookup.searched.join(', ')}. Install one (apt-get install chromium, or npx playwright install chromium) or set SHADELAB_CHROMIUM to a Chromium binary.`;
}

/**
 * The launch flags that make every render the same pixels on every machine: WebGL through ANGLE on
 * SwiftShader (the CPU), explicitly allowed (Chromium no longer falls back to it by itself, and without a GPU
 * a page then has no WebGL at all), and no background traffic.
 * @type {string[]}
 */
export const chromiumArgs = [
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--no-first-run',
];

/**
 * Added to {@link chromiumArgs} for WebGPU: Chromium then exposes a WebGPU adapter (SwiftShader's, a fallback
 * adapter, on a machine without a GPU).
 * @type {string[]}
 */
export const webgpuArgs = ['--enable-unsafe-webgpu'];
