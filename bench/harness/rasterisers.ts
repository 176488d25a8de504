// Harness of bench/rasterisers.bench.mjs: the same scene drawn by different rasterisers and settings, read back
// as RGBA (base64) for the bench to measure how far they differ: ShadingMaterial through WebGLRenderer with and
// without MSAA and with the camera shifted by a fraction of a pixel (as another GPU's sub-pixel snapping would
// place the vertices), and three's own MeshPhongNodeMaterial through WebGPURenderer on its WebGPU backend and
// on its WebGL2 backend (forceWebGL); and, through @shadelab/playwright's page side (what toMatchAcrossRenderers
// draws with), three's MeshPhongMaterial on WebGLRenderer and on both WebGPURenderer backends. The bench opens
// this page in headless Chromium (SwiftShader) and in headed Chromium on Xvfb (Mesa's llvmpipe).
import { exposeRenderers, registerScene } from '@shadelab/playwright/page';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import { WebGLRenderer } from 'three';
import {
  AmbientLight,
  Color,
  Mesh,
  MeshPhongNodeMaterial,
  PerspectiveCamera,
  PointLight,
  RenderTarget,
  Scene,
  WebGPURenderer,
} from 'three/webgpu';
import { buildKitScene, type KitSceneOptions } from '../../tests/harness/kitScene';

function base64(bytes: Uint8Array): string {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

/** The kit's scene through WebGLRenderer, RGBA rows bottom-up, as base64. */
function renderShading(options: KitSceneOptions): string {
  const kit = buildKitScene(options);
  const renderer = new WebGLRenderer({
    canvas: document.createElement('canvas'),
    antialias: kit.antialias,
    preserveDrawingBuffer: true,
  });
  renderer.setPixelRatio(1);
  renderer.setSize(kit.width, kit.height, false);
  renderer.setClearColor(kit.clearColor, 1);
  renderer.render(kit.scene, kit.camera);
  const gl = renderer.getContext();
  const pixels = new Uint8Array(kit.width * kit.height * 4);
  gl.readPixels(0, 0, kit.width, kit.height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  renderer.dispose();
  renderer.forceContextLoss();
  return base64(pixels);
}

/**
 * The lecture's ellipsoid with three's MeshPhongNodeMaterial through WebGPURenderer into a render target (a
 * WebGPU canvas cannot present headless), read back; `backend` says which backend drew it.
 */
async function renderNode(
  width: number,
  height: number,
  forceWebGL: boolean,
): Promise<{ backend: string; pixels: string }> {
  const renderer = new WebGPURenderer({
    canvas: document.createElement('canvas'),
    forceWebGL,
    antialias: false,
  });
  await renderer.init();
  const backend = (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend ? 'webgpu' : 'webgl2';
  const scene = new Scene();
  scene.background = new Color(0, 0, 1);
  const material = new MeshPhongNodeMaterial({ color: new Color(0.6, 0.35, 0.2), shininess: 32 });
  material.specular = new Color(0.5, 0.5, 0.5);
  const mesh = new Mesh(
    new SubdivisionSphereGeometry({ base: 'icosahedron', level: 6, normals: 'smooth' }),
    material,
  );
  mesh.scale.set(2, 1, 2);
  scene.add(mesh);
  // Intensities × π: three's Lambert term divides by π, so these light it as the lecture's Id = 1, Ia = 0.2 do.
  const light = new PointLight(0xffffff, Math.PI, 0, 0);
  light.position.set(-5, 10, 20);
  scene.add(light, new AmbientLight(0xffffff, 0.2 * Math.PI));
  const camera = new PerspectiveCamera(90, width / height, 0.1, 10);
  camera.position.set(0, 0, 3);
  const target = new RenderTarget(width, height);
  // The target is the output: sRGB-encoded, as the canvas would show it.
  renderer.setOutputRenderTarget(target);
  renderer.setRenderTarget(target);
  await renderer.renderAsync(scene, camera);
  const pixels = (await renderer.readRenderTargetPixelsAsync(target, 0, 0, width, height)) as Uint8Array;
  target.dispose();
  renderer.dispose();
  return { backend, pixels: base64(new Uint8Array(pixels.buffer, pixels.byteOffset, pixels.byteLength)) };
}

/**
 * The ellipsoid of renderNode with three's MeshPhongMaterial (converted to its node material on WebGPURenderer), for
 * the kit's renderers: the variation between three's renderers with three's own material.
 */
registerScene('three-phong', ({ THREE, width, height }) => {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0, 0, 1);
  const material = new THREE.MeshPhongMaterial({ color: new THREE.Color(0.6, 0.35, 0.2), shininess: 32 });
  material.specular = new THREE.Color(0.5, 0.5, 0.5);
  const mesh = new THREE.Mesh(
    new SubdivisionSphereGeometry({ base: 'icosahedron', level: 6, normals: 'smooth' }),
    material,
  );
  mesh.scale.set(2, 1, 2);
  const light = new THREE.PointLight(0xffffff, Math.PI, 0, 0);
  light.position.set(-5, 10, 20);
  scene.add(mesh, light, new THREE.AmbientLight(0xffffff, 0.2 * Math.PI));
  const camera = new THREE.PerspectiveCamera(90, width / height, 0.1, 10);
  camera.position.set(0, 0, 3);
  return { scene, camera };
});
exposeRenderers();

declare global {
  interface Window {
    rasterisers: { renderShading: typeof renderShading; renderNode: typeof renderNode };
  }
}
window.rasterisers = { renderShading, renderNode };
document.body.dataset['ready'] = '1';
