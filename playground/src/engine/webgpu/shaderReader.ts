/** The node material's generated code, as the running backend compiled it (for the shader panel). */
import { provokingVertexOf, type ShadingNodeMaterial } from '@shadelab/material/webgpu';
import * as THREE from 'three';
import type { WebGPURenderer } from 'three/webgpu';
import { flatFor } from './scene';
import type { GeneratedShader, GpuHost } from './status';

/** `material` on the host mesh's geometry and place, compiled alone: its WGSL or GLSL (or why it failed). */
export async function generatedShader(
  renderer: WebGPURenderer,
  host: GpuHost,
  material: ShadingNodeMaterial,
): Promise<GeneratedShader> {
  const { mesh, camera } = host;
  const probe = new THREE.Mesh(flatFor(mesh.geometry, provokingVertexOf(renderer)), material);
  probe.matrixWorld.copy(mesh.matrixWorld);
  probe.matrixAutoUpdate = false;
  probe.matrixWorldAutoUpdate = false;
  const scene = new THREE.Scene();
  scene.add(probe);
  const saved = camera.coordinateSystem;
  const webgpu = (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend === true;
  const language = webgpu ? 'WGSL' : 'GLSL';
  try {
    const { vertexShader, fragmentShader } = await renderer.debug.getShaderAsync(scene, camera, probe);
    return { language, vertexShader: vertexShader ?? '', fragmentShader: fragmentShader ?? '' };
  } catch (error) {
    const text = `// The generated shader could not be read: ${error instanceof Error ? error.message : error}`;
    return { language, vertexShader: text, fragmentShader: text };
  } finally {
    camera.coordinateSystem = saved;
    (camera as THREE.PerspectiveCamera).updateProjectionMatrix?.();
    scene.remove(probe);
  }
}
