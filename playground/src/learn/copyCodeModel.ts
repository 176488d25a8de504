/**
 * Copy as code, step 1: what of the playground's state a program needs. Each object is the packages' own
 * options with only the values that differ from the packages' defaults, read from the classes themselves (a
 * fresh `ShadingMaterial`, `PhongLight`, `Trackball`, `OutlineMaterial`), so that the generated code is
 * minimal and follows the packages. The emitters (`copyCodeThree.ts`, `copyCodeR3f.ts`) only print it.
 */
import { PhongLight, ShadingMaterial } from '@shadelab/material';
import { OutlineMaterial } from '@shadelab/material/outline';
import { Trackball } from '@shadelab/trackball';
import type { DepthMode, PlaygroundState, SceneName, Vec3 } from '../state/schema';

/** A value the code writes out: a number, a string, a boolean, a list, or an object literal. */
export type Literal = number | string | boolean | readonly Literal[] | { readonly [key: string]: Literal };
/** An options object literal: only the keys that differ from the defaults. */
export type Options = Record<string, Literal>;

/** The camera as the code sets it: `lookAt(eye, at, up)`, then the projection. */
export type CodeCamera = { eye: Vec3; at: Vec3; up: Vec3 } & (
  | { projection: 'perspective'; fovy: number; near: number; far: number }
  | {
      projection: 'orthographic';
      /** The lecture's r, l, t, b. */
      box: [number, number, number, number];
      near: number;
      far: number;
      /** r and l follow the canvas's aspect (the camera's `setAspect`). */
      fitAspect: boolean;
      /** The camera's zoom, set before the projection; null when 1. */
      zoom: number | null;
    }
);

/** What is drawn in place of the lecture's sphere. */
export type CodeObject =
  | {
      kind: 'mesh';
      /** SubdivisionSphereGeometry options. */
      geometry: Options;
      /** Flat shading: the geometry prepared by `flatShadingGeometry`. */
      flat: boolean;
    }
  /** AutoDetailSphere (`@shadelab/sphere/detail`) options. */
  | { kind: 'auto'; options: Options }
  /** The ray-cast SphereImpostor, scaled by the radius (the impostor is a unit sphere). */
  | { kind: 'impostor'; radius: number }
  /** One of the playground's demo scenes, or a glTF model. */
  | { kind: 'scene'; name: Exclude<SceneName, 'sphere'>; flat: boolean };

/** Everything the generated program sets. */
export interface CodeScene {
  /** The renderer's depth mode (`depthBufferParameters`); null for three's standard depth buffer. */
  depth: DepthMode | null;
  camera: CodeCamera;
  /** The PhongLights: constructor options and position (null at the origin). */
  lights: { options: Options; position: Vec3 | null }[];
  /** ShadingMaterial options (shading included); for a model, the `swapMaterials` options. */
  material: Options;
  /** OutlineMaterial options of the cel outline (`createOutline`); null when no outline is drawn. */
  outline: Options | null;
  object: CodeObject;
  /** The model scale of the lecture's sphere; null when (1, 1, 1) or a demo scene is drawn. */
  scale: Vec3 | null;
  /** The object's starting orientation (the trackball's accumulated turn), [x, y, z, w]; null when none. */
  rotation: [number, number, number, number] | null;
  /** Trackball options. */
  trackball: Options;
  /** Whether the trackball spins on after a fling (the program then steps it every frame). */
  damping: boolean;
}

/**
 * The state fields the code does not reproduce, and why. Every other field of the state is in the code
 * ({@link codeScene}); the unit tests check that the two sets cover the state.
 */
export const NOT_EXPORTED: Readonly<Record<string, string>> = {
  view: 'the compare and parity views are the playground’s; the code draws the single view',
  renderer:
    'the code draws with WebGLRenderer and ShadingMaterial (WebGPU: ShadingNodeMaterial, @shadelab/material/webgpu)',
  'camera.dragTurns': 'the playground’s navigation (CameraMovement), not the scene',
  'camera.turnSpeed': 'the playground’s navigation (CameraMovement), not the scene',
  'camera.moveSpeed': 'the playground’s navigation (CameraMovement), not the scene',
};

const same = (a: readonly number[], b: readonly number[]) =>
  a.length === b.length && a.every((v, i) => v === b[i]);

/** The packages' defaults, read from fresh objects once. */
function packageDefaults() {
  const material = new ShadingMaterial();
  const light = new PhongLight();
  const trackball = new Trackball(null, null);
  const outline = new OutlineMaterial();
  const defaults = {
    material: {
      shading: material.shading,
      lighting: material.lighting,
      celBands: material.celBands,
      ka: material.ka.toArray(),
      kd: material.kd.toArray(),
      ks: material.ks.toArray(),
      shininess: material.shininess,
    } as Record<string, Literal>,
    light: {
      ambient: light.ambient.toArray(),
      diffuse: light.diffuse.toArray(),
      specular: light.specular.toArray(),
      attenuation: { ...light.attenuation },
    },
    trackball: {
      mapping: trackball.mapping,
      rotateSpeed: trackball.rotateSpeed,
      zoomSpeed: trackball.zoomSpeed,
      minZoom: trackball.minZoom,
      maxZoom: trackball.maxZoom,
      radius: trackball.radius,
      dampingFactor: trackball.dampingFactor,
    } as Record<string, Literal>,
    outline: { thickness: outline.thickness, color: `#${outline.color.getHexString()}` },
  };
  // Options the material gained later (the term views' `output`, the teaching `normalMatrix`) are read the same way.
  for (const key of ['output', 'normalMatrix']) {
    const value = (material as unknown as Record<string, unknown>)[key];
    if (typeof value === 'string') defaults.material[key] = value;
  }
  material.dispose();
  outline.dispose();
  trackball.dispose();
  return defaults;
}

let cached: ReturnType<typeof packageDefaults> | null = null;
/** The packages' defaults (read on first use). */
export function defaults(): ReturnType<typeof packageDefaults> {
  cached ??= packageDefaults();
  return cached;
}

/** The keys of `value` whose value differs from `base`'s (arrays compared by element). */
function differing(value: Record<string, Literal>, base: Record<string, Literal>): Options {
  const out: Options = {};
  for (const [key, v] of Object.entries(value)) {
    const d = base[key];
    const equal = Array.isArray(v) && Array.isArray(d) ? same(v as number[], d as number[]) : v === d;
    if (!equal) out[key] = v;
  }
  return out;
}

/** The SubdivisionSphereGeometry's defaults (`@shadelab/sphere`'s SubdivideSphereOptions). */
const SPHERE_DEFAULTS: Record<string, Literal> = { base: 'tetrahedron', level: 6, radius: 1 };
/** AutoDetailSphere's defaults for what the playground sets. */
const AUTO_DETAIL_DEFAULTS: Record<string, Literal> = { maxErrorPx: 0.5, radius: 1 };

/** The material options of the state that the code sets (only those that differ from ShadingMaterial's). */
function materialOptions(m: PlaygroundState['material'], keys?: readonly string[]): Options {
  const base = defaults().material;
  const values: Record<string, Literal> = {};
  for (const key of Object.keys(base)) {
    if (keys && !keys.includes(key)) continue;
    const value = (m as unknown as Record<string, Literal | undefined>)[key];
    if (value !== undefined) values[key] = value;
  }
  return differing(values, base);
}

/** What the code needs from a (valid) playground state. Pure: the same state gives the same description. */
export function codeScene(state: PlaygroundState): CodeScene {
  const { material: m, camera: c, trackball: t, sphere: s } = state;
  const d = defaults();
  const lights = state.lights.map((light) => {
    const { attenuation, ...colours } = light;
    const options = differing(
      { ambient: colours.ambient, diffuse: colours.diffuse, specular: colours.specular },
      d.light,
    );
    const att = differing({ ...attenuation }, d.light.attenuation);
    if (Object.keys(att).length > 0) options['attenuation'] = att;
    const position = light.position.every((v) => v === 0) ? null : light.position;
    return { options, position };
  });
  const drawsCel = m.celBands > 0;
  const outline =
    m.outline && drawsCel && !(state.scene === 'sphere' && s.render === 'impostor')
      ? differing({ thickness: m.outlineWidth, color: m.outlineColor }, d.outline)
      : null;
  const flat = m.shading === 'flat';
  const object: CodeObject =
    state.scene !== 'sphere'
      ? { kind: 'scene', name: state.scene, flat }
      : s.render === 'impostor'
        ? { kind: 'impostor', radius: s.radius }
        : s.auto
          ? {
              kind: 'auto',
              options: {
                ...differing({ maxErrorPx: s.maxErrorPx, radius: s.radius }, AUTO_DETAIL_DEFAULTS),
                ...(flat ? { indexed: false } : {}),
              },
            }
          : {
              kind: 'mesh',
              geometry: {
                ...differing({ base: s.base, level: s.level, radius: s.radius }, SPHERE_DEFAULTS),
                normals: 'none',
              },
              flat,
            };
  let material = materialOptions(m);
  // The impostor is ray-cast per pixel (no shading), and the playground gives it neither the term view nor the
  // normal matrix mode; a model's swap takes the shading, lighting and cel bands.
  if (object.kind === 'impostor') {
    for (const key of ['shading', 'output', 'normalMatrix']) delete material[key];
  }
  if (state.scene === 'model') material = materialOptions(m, ['shading', 'lighting', 'celBands']);
  const camera: CodeCamera =
    c.projection === 'perspective'
      ? { eye: c.eye, at: c.at, up: c.up, projection: 'perspective', fovy: c.fovy, near: c.near, far: c.far }
      : {
          eye: c.eye,
          at: c.at,
          up: c.up,
          projection: 'orthographic',
          box: [c.right, c.left, c.top, c.bottom],
          near: c.near,
          far: c.far,
          fitAspect: c.fitAspect,
          zoom: c.zoom === 1 ? null : c.zoom,
        };
  const trackball = differing(
    {
      mapping: t.mapping,
      rotateSpeed: t.rotateSpeed,
      zoomSpeed: t.zoomSpeed,
      minZoom: t.minZoom,
      maxZoom: t.maxZoom,
      radius: t.radius,
      ...(t.damping ? { dampingFactor: t.dampingFactor } : {}),
    },
    d.trackball,
  );
  if (t.damping) trackball['enableDamping'] = true;
  const [x, y, z, w] = t.rotation;
  // The impostor is a unit sphere: the radius scales it with the model scale.
  const scale = state.model.scale.map((v) => (object.kind === 'impostor' ? v * s.radius : v)) as Vec3;
  return {
    depth: c.depth === 'standard' ? null : c.depth,
    camera,
    lights,
    material,
    outline,
    object,
    scale: object.kind === 'scene' || same(scale, [1, 1, 1]) ? null : scale,
    rotation: x === 0 && y === 0 && z === 0 ? null : [x, y, z, w],
    trackball,
    damping: t.damping,
  };
}
