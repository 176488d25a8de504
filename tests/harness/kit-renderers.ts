// Harness of tests/playwright-kit-renderers.spec.ts and tests/playwright-kit-rasterisers.spec.ts: the page side of
// toMatchAcrossRenderers, as a user's test page has it. It exposes the kit's renderers with the page's own
// classes (ShadingMaterial for WebGLRenderer, ShadingNodeMaterial for WebGPURenderer, PhongLight, the subdivided
// sphere) for factories written in the tests, and registers the lecture's ellipsoid as a named scene.
import { PhongLight, ShadingMaterial } from '@shadelab/material';
import { ShadingNodeMaterial } from '@shadelab/material/webgpu';
import { exposeRenderers, registerScene } from '@shadelab/playwright/page';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';

exposeRenderers({ PhongLight, ShadingMaterial, ShadingNodeMaterial, SubdivisionSphereGeometry });

/** The lecture's ellipsoid, lit by one PhongLight, in the shading `arg.shading` (default phong). */
registerScene('lecture', ({ THREE, kind, arg, width, height }) => {
  const { shading = 'phong' } = (arg ?? {}) as { shading?: 'flat' | 'gouraud' | 'phong' };
  const scene = new THREE.Scene();
  const light = new PhongLight({ ambient: 0.2, diffuse: 1, specular: 0.8 });
  light.position.set(-5, 10, 20);
  const options = { shading, shininess: 32, lights: [light] } as const;
  const material = kind === 'webgl' ? new ShadingMaterial(options) : new ShadingNodeMaterial(options);
  const sphere = new THREE.Mesh(new SubdivisionSphereGeometry({ level: 5, normals: 'none' }), material);
  sphere.scale.set(2, 1, 2);
  scene.add(light, sphere);
  const camera = new THREE.PerspectiveCamera(90, width / height, 0.1, 10);
  camera.position.set(0, 0, 3);
  return { scene, camera, clearColor: 0x0000ff };
});
