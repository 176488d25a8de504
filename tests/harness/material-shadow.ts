// Harness for tests/material-shadow.spec.ts: a ground plane that receives the shadow of an occluder (outside the
// view) from one of three's shadow-casting lights. Where the shadow falls is judged against three's own
// MeshPhongMaterial (the pixels its shadow darkens); colours against shade() with the light's colour times three's
// shadow factor (1 − shadow.intensity in full shadow, 1 in the light).
import {
  flatShadingGeometry,
  linearToSrgb8,
  PhongLight,
  type ShadeLight,
  type ShadeThreeLight,
  type Shading,
  ShadingMaterial,
  shade,
} from '@shadelab/material';
import { SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { createOutline } from '@shadelab/material/outline';
import {
  AmbientLight,
  BasicShadowMap,
  BoxGeometry,
  type BufferGeometry,
  type Camera,
  Color,
  DataTexture,
  DirectionalLight,
  DoubleSide,
  type Light,
  type Material,
  Mesh,
  MeshBasicMaterial,
  MeshPhongMaterial,
  OrthographicCamera,
  PCFShadowMap,
  PerspectiveCamera,
  Plane,
  PlaneGeometry,
  PointLight,
  Raycaster,
  Scene,
  SpotLight,
  Vector2,
  Vector3,
  WebGLRenderer,
} from 'three';
import { readCanvas } from './lib/pixels';

export interface ShadowConfig {
  shading: Shading;
  /** The shadow-casting light. */
  light: 'directional' | 'spot' | 'point';
  /** three's shadow map type. @default 'basic' */
  mapType?: 'basic' | 'pcf';
  /** The plane's receiveShadow. @default true */
  receive?: boolean;
  /** The light's shadow.intensity. @default 1 */
  intensity?: number;
  /** ks of the plane (0 makes a directional light's colours constant over the plane). @default 0 */
  ks?: number;
  /** Shininess of the plane (0: a uniform highlight, constant over the plane for a directional light). @default 16 */
  shininess?: number;
  /** Cel bands of the plane's material. @default 0 */
  celBands?: number;
  /** A uniform texture (linear TEXEL) as the plane's map: it multiplies ka and kd. @default false */
  map?: boolean;
  /** DoubleSide on the plane. @default false */
  doubleSide?: boolean;
  /** An attenuated PhongLight in the scene too. @default false */
  phongLight?: boolean;
  /**
   * The camera looking down at the plane: perspective, orthographic, or perspective with a view matrix scaled by
   * 1/2 (not rigid: the material then lights in world space). @default 'perspective'
   */
  camera?: 'perspective' | 'orthographic' | 'scaled';
  /** Pixels per side. @default 160 */
  size?: number;
}

export interface ShadowStats {
  /** Pixels the shadow darkens (by more than 2/255 on some channel): three's material / ShadingMaterial. */
  oracleShadowed: number;
  shadowed: number;
  /** Pixels whose 3 × 3 neighbourhood is all shadowed or all lit for three's material, and how many differ. */
  maskCompared: number;
  maskMismatches: number;
  /** Pixels compared with shade() (3 × 3 uniform), the largest difference (1/255) and how many exceed 2. */
  compared: number;
  maxError: number;
  mismatches: number;
  /** Of those, pixels in full shadow. */
  shadowCompared: number;
  /** The variant lit the plane in view space (SHADING_VIEW_SPACE). */
  viewSpace: boolean;
  worst: { x: number; y: number; ours: number[]; expected: number[] } | null;
}

const canvas = document.getElementById('viewport') as HTMLCanvasElement;
const renderer = new WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.shadowMap.enabled = true;

const KD: [number, number, number] = [0.6, 0.35, 0.2];
const TEXEL = [200, 220, 255] as const;
const AMBIENT = 0.2;
const LIGHT_POSITION: [number, number, number] = [-3, 4, 0];

function makeLight(kind: ShadowConfig['light']): DirectionalLight | SpotLight | PointLight {
  const color = new Color(1, 0.95, 0.9);
  let light: DirectionalLight | SpotLight | PointLight;
  if (kind === 'directional') {
    light = new DirectionalLight(color, 1.5);
    light.shadow.camera.left = -4;
    light.shadow.camera.right = 4;
    light.shadow.camera.top = 4;
    light.shadow.camera.bottom = -4;
  } else if (kind === 'spot') {
    light = new SpotLight(color, 30, 0, Math.PI / 4, 0, 2);
  } else {
    light = new PointLight(color, 30, 0, 2);
  }
  light.position.set(...LIGHT_POSITION);
  light.castShadow = true;
  light.shadow.mapSize.set(512, 512);
  light.shadow.camera.near = 0.5;
  light.shadow.camera.far = 20;
  return light;
}

/** What shade() takes for the light, its colour scaled by `visibility` (three's shadow factor). */
function shadeLight(light: Light, visibility: number): ShadeThreeLight {
  const color = light.color
    .clone()
    .multiplyScalar(light.intensity * visibility)
    .toArray();
  const position = light.getWorldPosition(new Vector3());
  if ((light as DirectionalLight).isDirectionalLight) {
    return { type: 'directional', color, direction: position.clone().normalize().toArray() };
  }
  const base = { color, position: position.toArray(), distance: 0, decay: 2 };
  if ((light as SpotLight).isSpotLight) {
    const spot = light as SpotLight;
    return {
      type: 'spot',
      ...base,
      direction: position.clone().normalize().toArray(),
      coneCos: Math.cos(spot.angle),
      penumbraCos: Math.cos(spot.angle * (1 - spot.penumbra)),
    };
  }
  return { type: 'point', ...base };
}

function render(scene: Scene, camera: Camera, size: number): Uint8Array {
  renderer.render(scene, camera);
  return readCanvas(renderer, size);
}

function shadowCompare(config: ShadowConfig): ShadowStats {
  const size = config.size ?? 160;
  renderer.setSize(size, size, false);
  renderer.shadowMap.type = config.mapType === 'pcf' ? PCFShadowMap : BasicShadowMap;
  renderer.shadowMap.needsUpdate = true;
  const scene = new Scene();
  const camera =
    config.camera === 'orthographic'
      ? new OrthographicCamera(-1.5, 1.5, 1.5, -1.5, 0.5, 20)
      : new PerspectiveCamera(40, 1, 0.5, 20);
  camera.position.set(0, 5, 0);
  camera.up.set(0, 0, -1);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  if (config.camera === 'scaled') {
    // three leaves a camera's scale out of its view matrix; set one that keeps it (not rigid).
    camera.matrixWorld.scale(new Vector3(2, 2, 2));
    camera.matrixWorldInverse.copy(camera.matrixWorld).invert();
    camera.matrixWorldAutoUpdate = false;
  }
  const phong = new PhongLight({
    ambient: 0.05,
    diffuse: [0.3, 0.5, 0.4],
    specular: 0.6,
    attenuation: { a: 1, b: 0.1, c: 0.05 },
  });
  phong.position.set(1, 1.5, -0.5);
  if (config.phongLight) scene.add(phong);
  const light = makeLight(config.light);
  light.shadow.intensity = config.intensity ?? 1;
  scene.add(light, new AmbientLight(0xffffff, AMBIENT));
  // The occluder: above the ground, outside the view, between the light and the visible ground.
  const occluder = new Mesh(new BoxGeometry(0.6, 0.1, 1.6), new MeshBasicMaterial());
  occluder.position.set(-1.9, 1.6, 0);
  occluder.castShadow = true;
  scene.add(occluder);
  const plane: BufferGeometry = new PlaneGeometry(4, 4, 8, 8).rotateX(-Math.PI / 2);
  const material = new ShadingMaterial({
    shading: config.shading,
    ka: KD,
    kd: KD,
    ks: config.ks ?? 0,
    shininess: config.shininess ?? 16,
    celBands: config.celBands ?? 0,
  });
  if (config.map) {
    const texture = new DataTexture(new Uint8Array([...TEXEL, 255]), 1, 1);
    texture.needsUpdate = true;
    material.map = texture;
  }
  if (config.doubleSide) material.side = DoubleSide;
  const ground = new Mesh<BufferGeometry, Material>(
    config.shading === 'flat' ? flatShadingGeometry(plane) : plane,
    material,
  );
  ground.receiveShadow = config.receive ?? true;
  scene.add(ground);
  scene.updateMatrixWorld();

  const renderWith = (m: Material, receive: boolean): Uint8Array => {
    ground.material = m;
    ground.receiveShadow = receive;
    renderer.shadowMap.needsUpdate = true;
    return render(scene, camera, size);
  };
  const receive = config.receive ?? true;
  const ours = renderWith(material, receive);
  const viewSpace = material.defines.SHADING_VIEW_SPACE !== undefined;
  const oursLit = renderWith(material, false);
  const oracle = new MeshPhongMaterial({ color: new Color(...KD), specular: 0x000000, shininess: 16 });
  const theirs = renderWith(oracle, true);
  const theirsLit = renderWith(oracle, false);
  oracle.dispose();

  const darker = (shadowed: Uint8Array, lit: Uint8Array, i: number) =>
    lit[4 * i] - shadowed[4 * i] > 2 ||
    lit[4 * i + 1] - shadowed[4 * i + 1] > 2 ||
    lit[4 * i + 2] - shadowed[4 * i + 2] > 2;
  const stats: ShadowStats = {
    oracleShadowed: 0,
    shadowed: 0,
    maskCompared: 0,
    maskMismatches: 0,
    compared: 0,
    maxError: 0,
    mismatches: 0,
    shadowCompared: 0,
    viewSpace,
    worst: null,
  };
  const eye: number[] = config.camera === 'orthographic' ? [0, 1, 0, 0] : camera.position.toArray();
  const phongShade: ShadeLight = {
    position: phong.position.toArray(),
    ambient: phong.ambient.toArray(),
    diffuse: phong.diffuse.toArray(),
    specular: phong.specular.toArray(),
    attenuation: phong.attenuation,
  };
  const raycaster = new Raycaster();
  const ground0 = new Plane(new Vector3(0, 1, 0), 0);
  const hit = new Vector3();
  const expected: [number, number, number] = [0, 0, 0];
  const ambient: ShadeThreeLight = { type: 'ambient', color: [AMBIENT, AMBIENT, AMBIENT] };
  const shadeMaterial = {
    ka: KD,
    kd: KD,
    ks: [config.ks ?? 0, config.ks ?? 0, config.ks ?? 0] as [number, number, number],
    shininess: config.shininess ?? 16,
    celBands: config.celBands ?? 0,
  };
  const tint = config.map ? TEXEL.map((c) => c / 255) : [1, 1, 1];
  const others = config.phongLight ? [ambient, phongShade] : [ambient];
  const litLights = [...others, shadeLight(light, 1)];
  const shadowLights = [...others, shadeLight(light, 1 - light.shadow.intensity)];
  for (let y = 1; y < size - 1; y++) {
    for (let x = 1; x < size - 1; x++) {
      const i = y * size + x;
      const a = darker(ours, oursLit, i);
      const b = darker(theirs, theirsLit, i);
      if (a) stats.shadowed++;
      if (b) stats.oracleShadowed++;
      let uniform = true;
      for (let dy = -1; uniform && dy <= 1; dy++)
        for (let dx = -1; uniform && dx <= 1; dx++)
          if (darker(theirs, theirsLit, i + dy * size + dx) !== b) uniform = false;
      if (!uniform) continue;
      stats.maskCompared++;
      if (a !== b) stats.maskMismatches++;
      // With a basic shadow map, a pixel is in full shadow or in full light (PCF blends the edge texels).
      if (config.mapType === 'pcf') continue;
      raycaster.setFromCamera(new Vector2(((x + 0.5) / size) * 2 - 1, ((y + 0.5) / size) * 2 - 1), camera);
      if (raycaster.ray.intersectPlane(ground0, hit) === null) continue;
      shade(
        { position: hit.toArray(), normal: [0, 1, 0], eye, tint },
        shadeMaterial,
        b && receive ? shadowLights : litLights,
        expected,
      );
      const code = linearToSrgb8(expected);
      const err = Math.max(
        Math.abs(ours[4 * i] - code[0]),
        Math.abs(ours[4 * i + 1] - code[1]),
        Math.abs(ours[4 * i + 2] - code[2]),
      );
      stats.compared++;
      if (b) stats.shadowCompared++;
      if (err > 2) stats.mismatches++;
      if (err > stats.maxError) {
        stats.maxError = err;
        stats.worst = { x, y, ours: [ours[4 * i], ours[4 * i + 1], ours[4 * i + 2]], expected: code };
      }
    }
  }
  material.map?.dispose();
  material.dispose();
  return stats;
}

/**
 * The impostor, the outline (which receive no shadow) and a ShadingMaterial whose mesh does not receive shadows, in a
 * scene with a shadow-casting light: pixels that differ from the same scene whose light casts none (0: they compile
 * and draw as before).
 */
function othersWithShadows(): { drawn: number; differing: number } {
  const size = 96;
  renderer.setSize(size, size, false);
  renderer.shadowMap.type = BasicShadowMap;
  const scene = new Scene();
  const camera = new PerspectiveCamera(40, 1, 0.5, 20);
  camera.position.set(0, 0, 6);
  const light = makeLight('directional');
  scene.add(light, new AmbientLight(0xffffff, AMBIENT));
  const impostor = new SphereImpostor(new SphereImpostorMaterial());
  impostor.position.set(-1, 0, 0);
  const mesh = new Mesh(new PlaneGeometry(1, 1, 2, 2), new ShadingMaterial({ shading: 'gouraud' }));
  mesh.position.set(1, 0, 0);
  mesh.castShadow = true;
  createOutline(mesh, { thickness: 0.1 });
  scene.add(impostor, mesh);
  scene.updateMatrixWorld();
  const draw = (cast: boolean): Uint8Array => {
    light.castShadow = cast;
    return render(scene, camera, size);
  };
  const a = draw(true);
  const b = draw(false);
  let drawn = 0;
  let differing = 0;
  for (let i = 0; i < size * size; i++) {
    if (a[4 * i] + a[4 * i + 1] + a[4 * i + 2] > 0) drawn++;
    if (a[4 * i] !== b[4 * i] || a[4 * i + 1] !== b[4 * i + 1] || a[4 * i + 2] !== b[4 * i + 2]) differing++;
  }
  return { drawn, differing };
}

/** Programs after turning receiveShadow and castShadow on and off `flips` times (bounded, not growing). */
function flipShadows(flips: number): { before: number; after: number } {
  const size = 32;
  renderer.setSize(size, size, false);
  const scene = new Scene();
  const camera = new PerspectiveCamera(40, 1, 0.5, 20);
  camera.position.set(0, 5, 0);
  camera.lookAt(0, 0, 0);
  const light = makeLight('directional');
  scene.add(light);
  const ground = new Mesh(new PlaneGeometry(4, 4).rotateX(-Math.PI / 2), new ShadingMaterial());
  scene.add(ground);
  render(scene, camera, size);
  const before = renderer.info.programs?.length ?? 0;
  for (let k = 0; k < flips; k++) {
    ground.receiveShadow = k % 2 === 0;
    light.castShadow = k % 3 !== 0;
    render(scene, camera, size);
  }
  return { before, after: renderer.info.programs?.length ?? 0 };
}

const api = { shadowCompare, flipShadows, othersWithShadows };

declare global {
  interface Window {
    shadowHarness: typeof api;
  }
}
window.shadowHarness = api;
document.body.dataset.ready = '1';
