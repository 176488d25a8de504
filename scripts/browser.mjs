// Which Chromium Playwright launches, and the flags it runs with. Order: $SHADELAB_CHROMIUM, Debian's
// /usr/bin/chromium, then Playwright's own browser (`npx playwright install chromium` on a laptop).
// The lookup and the flags are @shadelab/playwright's (what users get to test their own scenes): this file
// re-exports its plain-JavaScript source, so that `npm test` and `npm start` can check for a browser before
// anything is built.
export {
  chromiumArgs,
  chromiumExecutable,
  DEBIAN_CHROMIUM,
  describeBrowserSearch,
  lookupChromium,
  webgpuArgs,
} from '../packages/playwright/src/chromium.js';

/** @typedef {import('../packages/playwright/src/chromium.js').ChromiumLookup} ChromiumLookup */
