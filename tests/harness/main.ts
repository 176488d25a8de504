// The harness page (/harness/?page=<name>): the tests' pages are one HTML page, which loads the module `page` names
// after giving it the canvas it draws into. Each page's module sets `document.body.dataset.ready = '1'` (or its own
// `window` API) when it is ready.

/**
 * The canvas `#viewport` (data-testid "viewport") a page draws into, styled by index.html: 'block' (sized by the
 * page, on black), 'framed' (400 × 300 at (50, 50), on dark grey: the pointer tests' page) or 'small' (128 × 128).
 * Pages without one make their own canvases or render targets.
 */
type Viewport = 'block' | 'framed' | 'small';

/** Each page: its module, its canvas, and whether DOM listeners are counted from before anything else runs. */
const PAGES: Record<string, { load: () => Promise<unknown>; viewport?: Viewport; countListeners?: boolean }> =
  {
    adaptive: { load: () => import('./adaptive'), viewport: 'block' },
    camera: { load: () => import('./camera'), viewport: 'framed' },
    dropin: { load: () => import('./dropin') },
    'gltf-maker': { load: () => import('./gltf-maker') },
    kit: { load: () => import('./kit'), viewport: 'block' },
    'kit-renderers': { load: () => import('./kit-renderers') },
    leaks: { load: () => import('./leaks'), viewport: 'small', countListeners: true },
    'material-output': { load: () => import('./material-output') },
    'material-shadow': { load: () => import('./material-shadow'), viewport: 'block' },
    material: { load: () => import('./material'), viewport: 'block' },
    'outline-impostor': { load: () => import('./outline-impostor'), viewport: 'block' },
    'parity-rows': { load: () => import('./parity-rows') },
    swap: { load: () => import('./swap'), viewport: 'block' },
    trackball: { load: () => import('./trackball'), viewport: 'framed' },
    tradeoff: { load: () => import('./tradeoff'), viewport: 'block' },
    'webgpu-impostor': { load: () => import('./webgpu-impostor') },
    'webgpu-material': { load: () => import('./webgpu-material') },
    'webgpu-outline': { load: () => import('./webgpu-outline') },
    'webgpu-reliability': { load: () => import('./webgpu-reliability') },
    'webgpu-scene': { load: () => import('./webgpu-scene') },
  };

/**
 * Counts the DOM event listeners alive on every EventTarget, as the browser dedupes them (the same type, listener
 * and capture flag on a target count once): `window.__listenerCount()`.
 */
function countListeners(): void {
  const live = new WeakMap<EventTarget, Map<string, Set<unknown>>>();
  let count = 0;
  const key = (type: string, options?: boolean | EventListenerOptions) =>
    `${type}|${typeof options === 'boolean' ? options : Boolean(options?.capture)}`;
  const add = EventTarget.prototype.addEventListener;
  const remove = EventTarget.prototype.removeEventListener;
  EventTarget.prototype.addEventListener = function (type, listener, options) {
    if (listener) {
      let byKey = live.get(this);
      if (!byKey) {
        byKey = new Map();
        live.set(this, byKey);
      }
      const k = key(type, options);
      let set = byKey.get(k);
      if (!set) {
        set = new Set();
        byKey.set(k, set);
      }
      if (!set.has(listener)) {
        set.add(listener);
        count++;
      }
    }
    return add.call(this, type, listener, options);
  };
  EventTarget.prototype.removeEventListener = function (type, listener, options) {
    if (live.get(this)?.get(key(type, options))?.delete(listener)) count--;
    return remove.call(this, type, listener, options);
  };
  (window as unknown as { __listenerCount: () => number }).__listenerCount = () => count;
}

const pageName = new URLSearchParams(location.search).get('page') ?? '';
const page = PAGES[pageName];
if (page === undefined) {
  throw new Error(
    `harness: ?page= names no page (got "${pageName}"; pages: ${Object.keys(PAGES).join(', ')})`,
  );
}
document.title = `shadelab harness: ${pageName}`;
if (page.countListeners) countListeners();
if (page.viewport !== undefined) {
  document.body.dataset.viewport = page.viewport;
  const canvas = document.createElement('canvas');
  canvas.id = 'viewport';
  canvas.dataset.testid = 'viewport';
  if (page.viewport === 'framed') [canvas.width, canvas.height] = [400, 300];
  if (page.viewport === 'small') [canvas.width, canvas.height] = [128, 128];
  document.body.append(canvas);
}
await page.load();

export {};
