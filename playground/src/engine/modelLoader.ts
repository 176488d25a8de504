/**
 * A user's glTF file into three.js objects: checked first (`gltfCheck.ts`: size, container, embedded resources,
 * extensions), then parsed by three's GLTFLoader. The loader, and meshopt's decoder for a file that needs it,
 * are imported on first use, so neither is in the page's first-load bundle.
 */
import type { AnimationClip, Object3D } from 'three';
import { checkModelBytes, ModelError } from './gltfCheck';

export { MODEL_MAX_BYTES, ModelError } from './gltfCheck';

/** A parsed model: its scene and animations as three's GLTFLoader made them. */
export interface LoadedModel {
  /** The file's name (shown in the page). */
  readonly name: string;
  readonly scene: Object3D;
  readonly animations: readonly AnimationClip[];
}

/**
 * Checks and parses a .glb or .gltf (embedded resources only). Rejects with a {@link ModelError} whose message
 * names the file and the problem (three's own errors are wrapped in one).
 */
export async function loadModel(name: string, bytes: ArrayBuffer): Promise<LoadedModel> {
  const checked = checkModelBytes(name, bytes);
  const { GLTFLoader } = await import('three/addons/loaders/GLTFLoader.js');
  const loader = new GLTFLoader();
  if (checked.meshopt) {
    const { MeshoptDecoder } = await import('three/addons/libs/meshopt_decoder.module.js');
    await MeshoptDecoder.ready;
    loader.setMeshoptDecoder(MeshoptDecoder);
  }
  let gltf: { scene: Object3D; animations: AnimationClip[] };
  try {
    gltf = await new Promise((resolve, reject) => {
      loader.parse(checked.data, '', resolve, reject);
    });
  } catch (error) {
    const message = error instanceof Error ? error.message : String(error);
    throw new ModelError(`"${name}" could not be read by three's GLTFLoader: ${message}`);
  }
  let meshes = 0;
  gltf.scene.traverse((object) => {
    if ((object as { isMesh?: boolean }).isMesh) meshes++;
  });
  if (meshes === 0) throw new ModelError(`"${name}" has no mesh to draw.`);
  return { name, scene: gltf.scene, animations: gltf.animations };
}
