/**
 * A user's glTF file into three.js objects: checked first (`gltfCheck.ts`: size, container, embedded resources,
 * extensions, then the Khronos glTF Validator), then parsed by three's GLTFLoader. The loader, the validator and
 * each decoder a file needs (meshopt, Draco, KTX2 / Basis) are imported on first use, so none of them is in the
 * page's first-load bundle, and a file without compressed meshes or textures loads no decoder.
 *
 * Draco's decoder and Basis's transcoder are WebAssembly files of the installed three package
 * (`examples/jsm/libs/draco/gltf/`, `libs/basis/`): DRACOLoader and KTX2Loader name them with
 * `new URL(file, import.meta.url)`, which Vite serves from node_modules in dev and writes into a build as hashed
 * assets (never copied into the repository). The loaders fetch them, into Web Workers of their own, the first
 * time a file needs them.
 */
import type { AnimationClip, Object3D, WebGLRenderer } from 'three';
import type { DRACOLoader } from 'three/addons/loaders/DRACOLoader.js';
import type { KTX2Loader } from 'three/addons/loaders/KTX2Loader.js';
import { checkModelBytes, ModelError } from './gltfCheck';
import { validateModel } from './gltfValidate';

export { MODEL_MAX_BYTES, ModelError } from './gltfCheck';

/** A parsed model: its scene and animations as three's GLTFLoader made them. */
export interface LoadedModel {
  /** The file's name (shown in the page). */
  readonly name: string;
  readonly scene: Object3D;
  readonly animations: readonly AnimationClip[];
}

// One loader of each for the page: each keeps its decoder and its workers for the next file.
let draco: Promise<DRACOLoader> | null = null;
let ktx2: Promise<KTX2Loader> | null = null;

function dracoLoader(): Promise<DRACOLoader> {
  // The decoder built for glTF's Draco (smaller than the general one), as WebAssembly.
  draco ??= import('three/addons/loaders/DRACOLoader.js').then(({ DRACOLoader, DRACO_GLTF_CONFIG }) =>
    new DRACOLoader().setDecoderPath(DRACO_GLTF_CONFIG),
  );
  return draco;
}

/**
 * The KTX2 loader, its output formats chosen for `renderer` (the viewer's WebGLRenderer): a compressed format the
 * GPU samples directly (ASTC, BC7, BC1/BC3 or ETC2, in KTX2Loader's order) or, where none is supported, RGBA8.
 * WebGPU mode draws the same textures with WebGPURenderer, so formats WebGPU has no counterpart of (PVRTC, and
 * ETC1 alone) are not chosen; each remaining format maps to a WebGPU texture-compression feature the same GPU
 * offers. Without a renderer (no viewer yet) the textures are transcoded to RGBA8, which every renderer reads.
 */
function ktx2Loader(renderer: WebGLRenderer | null): Promise<KTX2Loader> {
  ktx2 ??= import('three/addons/loaders/KTX2Loader.js').then(({ KTX2Loader }) => {
    const loader = new KTX2Loader();
    if (renderer) loader.detectSupport(renderer);
    else
      loader.workerConfig = {
        astcSupported: false,
        astcHDRSupported: false,
        etc1Supported: false,
        etc2Supported: false,
        dxtSupported: false,
        bptcSupported: false,
        pvrtcSupported: false,
      };
    loader.workerConfig.etc1Supported = false;
    loader.workerConfig.pvrtcSupported = false;
    return loader;
  });
  return ktx2;
}

/**
 * Checks and parses a .glb or .gltf (embedded resources only). Rejects with a {@link ModelError} whose message
 * names the file and the problem (three's own errors are wrapped in one). `renderer`: the viewer's, for which
 * KTX2 textures are transcoded.
 */
export async function loadModel(
  name: string,
  bytes: ArrayBuffer,
  renderer: WebGLRenderer | null = null,
): Promise<LoadedModel> {
  const checked = checkModelBytes(name, bytes);
  await validateModel(name, checked);
  const { GLTFLoader } = await import('three/addons/loaders/GLTFLoader.js');
  const loader = new GLTFLoader();
  if (checked.decoders.meshopt) {
    const { MeshoptDecoder } = await import('three/addons/libs/meshopt_decoder.module.js');
    await MeshoptDecoder.ready;
    loader.setMeshoptDecoder(MeshoptDecoder);
  }
  if (checked.decoders.draco) loader.setDRACOLoader(await dracoLoader());
  if (checked.decoders.ktx2) loader.setKTX2Loader(await ktx2Loader(renderer));
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
