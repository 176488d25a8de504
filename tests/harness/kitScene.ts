// The scene of the @shadelab/playwright tests (tests/playwright-kit.spec.ts): the lecture's lit ellipsoid, built
// by one function that the harness page (kit.ts) draws and the spec reads in Node with referenceSceneOf, as a
// user's test reads the scene their app builds.
import { Camera } from '@shadelab/camera';
import { flatShadingGeometry, PhongLight, ShadingMaterial } from '@shadelab/material';
import { SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { type SphereBase, SubdivisionSphereGeometry } from '@shadelab/sphere';
import { Color, Matrix4, Mesh, type Object3D, Scene } from 'three';

/** What the kit's scene varies (the lecture's scene by default). */
export interface KitSceneOptions {
  /** Canvas size in pixels. @default 320 × 240 */
  width?: number;
  height?: number;
  /** @default 'phong' */
  shading?: 'flat' | 'gouraud' | 'phong' | 'impostor';
  /** Subdivision sphere base and level of the mesh shadings. @default 'icosahedron', 6 */
  base?: SphereBase;
  level?: number;
  /** @default 32 */
  shininess?: number;
  /** @default 'phong' */
  lighting?: 'phong' | 'blinn-phong';
  /** Cel bands (0: off). @default 0 */
  celBands?: number;
  /** The ellipsoid's semi-axes. @default [2, 1, 2] */
  scale?: [number, number, number];
  /** The light's position. @default [-5, 10, 20] */
  light?: [number, number, number];
  /** Clear colour, linear RGB. @default [0, 0, 1] (pure blue, which the shading never produces) */
  background?: [number, number, number];
  /** Renderer antialiasing (MSAA). @default false */
  antialias?: boolean;
  /**
   * Shift the picture by this many pixels (x right, y up), as another GPU's sub-pixel grid would place the
   * vertices. @default [0, 0]
   */
  shiftPx?: [number, number];
}

/** The scene, camera and sphere of `options`, and the options resolved. */
export function buildKitScene(options: KitSceneOptions = {}) {
  const {
    width = 320,
    height = 240,
    shading = 'phong',
    base = 'icosahedron',
    level = 6,
    shininess = 32,
    lighting = 'phong',
    celBands = 0,
    scale = [2, 1, 2],
    light: lightPosition = [-5, 10, 20],
    background = [0, 0, 1],
    antialias = false,
    shiftPx = [0, 0],
  } = options;
  const scene = new Scene();
  scene.background = null;
  const light = new PhongLight({ ambient: 0.2, diffuse: 1, specular: 0.8 });
  light.position.set(...lightPosition);
  scene.add(light);
  let sphere: Object3D;
  if (shading === 'impostor') {
    sphere = new SphereImpostor(
      new SphereImpostorMaterial({ shininess, lighting, celBands, lights: [light] }),
    );
  } else {
    const geometry = new SubdivisionSphereGeometry({ base, level, normals: 'none' });
    const material = new ShadingMaterial({ shading, shininess, lighting, celBands, lights: [light] });
    sphere = new Mesh(shading === 'flat' ? flatShadingGeometry(geometry) : geometry, material);
  }
  sphere.scale.set(...scale);
  scene.add(sphere);
  const camera = new Camera();
  camera.lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
  camera.setPerspective(90, width / height, 0.1, 10);
  if (shiftPx[0] !== 0 || shiftPx[1] !== 0) {
    camera.projectionMatrix.premultiply(
      new Matrix4().makeTranslation((2 * shiftPx[0]) / width, (2 * shiftPx[1]) / height, 0),
    );
    camera.projectionMatrixInverse.copy(camera.projectionMatrix).invert();
  }
  return {
    scene,
    camera,
    sphere,
    light,
    width,
    height,
    antialias,
    background,
    clearColor: new Color(...background),
  };
}
