// The trade-off page's first view and option: the playground's URL state (`#s=…`, same schema and parser)
// mapped onto the trade-off scene when there is one, else the lecture's.
import { readUrlState } from '../state/persist';
import type { SceneName } from '../state/schema';
import type { TradeOption, TradeView } from './tradeOption';

/** The live view's size, px. */
export const WIDTH = 640;
export const HEIGHT = 360;
/** The highest level the page draws live (and auto detail picks; tests/tradeoff-page.spec.ts expects 7). */
export const MAX_LEVEL = 7;

export interface Initial {
  view: TradeView;
  option: TradeOption;
  /** The playground scene the URL names when it is not the lecture's sphere, which this page draws instead. */
  otherScene: SceneName | null;
}

/** The playground's state from the URL, mapped onto the trade-off scene (camera looks at the origin). */
export function initialFromUrl(): Initial {
  const view: TradeView = { width: WIDTH, height: HEIGHT };
  const parsed = readUrlState();
  if (parsed === null || !parsed.ok) {
    return { view, option: { shading: 'phong', base: 'tetrahedron', level: 6 }, otherScene: null };
  }
  const { material, lights, model, camera, sphere, scene } = parsed.state;
  return {
    otherScene: scene === 'sphere' ? null : scene,
    view: {
      ...view,
      projection: camera.projection,
      fovy: camera.fovy,
      eye: camera.eye,
      scale: model.scale,
      lights: lights.length > 0 ? lights : undefined,
      lighting: material.lighting,
      celBands: material.celBands,
      shininess: material.shininess,
      ka: material.ka,
      kd: material.kd,
      ks: material.ks,
    },
    option: { shading: material.shading, base: sphere.base, level: Math.min(sphere.level, MAX_LEVEL) },
  };
}
