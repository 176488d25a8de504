/**
 * What the playground checks in a user's glTF file before three's GLTFLoader sees it. First, here and at once:
 * its size, its container (a GLB's header and chunks, or JSON text), that every buffer and image is inside the
 * file, and that three can decode every extension it requires ({@link checkModelBytes}). Then the Khronos glTF
 * Validator checks the rest of the spec (`gltfValidate.ts`, loaded with the model loader, not at the page's
 * start). Each refusal is a {@link ModelError} whose message the page shows as it is. No three, no DOM:
 * unit-tested in gltfCheck.test.ts.
 */

/** Largest file the playground reads, bytes (64 MiB); a GLB header claiming more is refused before parsing. */
export const MODEL_MAX_BYTES = 64 * 1024 * 1024;

/** A file refused: the message names the file and what is wrong with it (shown in the page). */
export class ModelError extends Error {
  override name = 'ModelError';
}

/** The parts of a glTF's JSON the checks read (everything else is the validator's and three's GLTFLoader's). */
export interface GltfJson {
  asset?: unknown;
  extensionsUsed?: unknown;
  extensionsRequired?: unknown;
  buffers?: unknown;
  images?: unknown;
  [key: string]: unknown;
}

/** A file that passed the checks. */
export interface CheckedModel {
  /** What `GLTFLoader.parse` takes: the GLB's bytes, or the .gltf's text. */
  readonly data: ArrayBuffer | string;
  readonly json: GltfJson;
  /** The decoders the file needs, each loaded only for a file that uses its extension. */
  readonly decoders: { readonly meshopt: boolean; readonly draco: boolean; readonly ktx2: boolean };
}

/** The meshopt extensions: decoded by three's pure-JS `meshopt_decoder.module.js`. */
export const MESHOPT_EXTENSIONS = ['EXT_meshopt_compression', 'KHR_meshopt_compression'] as const;
/** Draco meshes: decoded by three's DRACOLoader with Google's WebAssembly decoder (three's `libs/draco/gltf/`). */
export const DRACO_EXTENSION = 'KHR_draco_mesh_compression';
/** KTX2 / Basis Universal textures: transcoded by three's KTX2Loader with three's `libs/basis/` transcoder. */
export const KTX2_EXTENSION = 'KHR_texture_basisu';
/** The extensions three r187's GLTFLoader reads (a required one outside these is refused). */
export const SUPPORTED_EXTENSIONS: readonly string[] = [
  'KHR_lights_punctual',
  'KHR_materials_clearcoat',
  'KHR_materials_diffuse_roughness',
  'KHR_materials_dispersion',
  'KHR_materials_ior',
  'KHR_materials_sheen',
  'KHR_materials_specular',
  'KHR_materials_transmission',
  'KHR_materials_iridescence',
  'KHR_materials_anisotropy',
  'KHR_materials_unlit',
  'KHR_materials_volume',
  'KHR_materials_emissive_strength',
  'KHR_texture_transform',
  'KHR_mesh_quantization',
  'EXT_materials_bump',
  'EXT_texture_webp',
  'EXT_texture_avif',
  'EXT_mesh_gpu_instancing',
  DRACO_EXTENSION,
  KTX2_EXTENSION,
  ...MESHOPT_EXTENSIONS,
];

const GLB_MAGIC = 0x46546c67; // 'glTF', little-endian
const CHUNK_JSON = 0x4e4f534a; // 'JSON'

/** Bytes as a reader sees them: "64 MiB", "2.0 GiB", "1,234 bytes". */
export function formatBytes(n: number): string {
  if (n >= 2 ** 30) return `${(n / 2 ** 30).toFixed(1)} GiB`;
  if (n >= 2 ** 20) return `${(n / 2 ** 20).toFixed(1).replace(/\.0$/, '')} MiB`;
  return `${n.toLocaleString('en')} bytes`;
}

/** Refuses a file larger than {@link MODEL_MAX_BYTES} before it is read. */
export function checkModelSize(name: string, size: number): void {
  if (size > MODEL_MAX_BYTES) {
    throw new ModelError(
      `"${name}" is ${formatBytes(size)}, more than the playground's limit of ${formatBytes(MODEL_MAX_BYTES)}.`,
    );
  }
  if (size === 0) throw new ModelError(`"${name}" is empty.`);
}

/** Checks a whole file's bytes (a .glb or a .gltf with embedded resources); throws {@link ModelError}. */
export function checkModelBytes(name: string, bytes: ArrayBuffer): CheckedModel {
  checkModelSize(name, bytes.byteLength);
  const view = new DataView(bytes);
  if (bytes.byteLength >= 4 && view.getUint32(0, true) === GLB_MAGIC) return checkGlb(name, bytes, view);
  const head = new Uint8Array(bytes, 0, Math.min(bytes.byteLength, 4));
  let start = head[0] === 0xef && head[1] === 0xbb && head[2] === 0xbf ? 3 : 0; // a UTF-8 BOM
  const all = new Uint8Array(bytes);
  while (
    start < all.length &&
    (all[start] === 0x20 || all[start] === 0x0a || all[start] === 0x0d || all[start] === 0x09)
  )
    start++;
  if (all[start] !== 0x7b /* { */) {
    const shown = Array.from(head, (b) => b.toString(16).padStart(2, '0')).join(' ');
    throw new ModelError(
      `"${name}" is not a glTF file: it starts with the bytes ${shown}, neither a GLB's magic "glTF" nor JSON text.`,
    );
  }
  const text = decodeText(name, all, 'the file');
  const json = parseJson(name, text);
  return { data: text, json, decoders: checkJson(name, json) };
}

function checkGlb(name: string, bytes: ArrayBuffer, view: DataView): CheckedModel {
  if (bytes.byteLength < 12)
    throw new ModelError(
      `"${name}" is truncated: ${bytes.byteLength} bytes, shorter than a GLB header (12).`,
    );
  const version = view.getUint32(4, true);
  if (version !== 2)
    throw new ModelError(`"${name}" is a GLB of version ${version}; only version 2 is read.`);
  const length = view.getUint32(8, true);
  if (length > MODEL_MAX_BYTES) {
    throw new ModelError(
      `"${name}": its GLB header claims ${formatBytes(length)}, more than the playground's limit of ${formatBytes(MODEL_MAX_BYTES)}; refused before reading it.`,
    );
  }
  if (length !== bytes.byteLength) {
    throw new ModelError(
      `"${name}" is ${length > bytes.byteLength ? 'truncated' : 'malformed'}: its GLB header says ${formatBytes(length)}, the file has ${formatBytes(bytes.byteLength)}.`,
    );
  }
  let json: GltfJson | null = null;
  for (let offset = 12; offset < length; ) {
    if (offset + 8 > length)
      throw new ModelError(`"${name}" is truncated: a chunk header at byte ${offset} runs past the end.`);
    const chunkLength = view.getUint32(offset, true);
    const type = view.getUint32(offset + 4, true);
    const end = offset + 8 + chunkLength;
    if (end > length) {
      throw new ModelError(
        `"${name}" is truncated: a chunk of ${formatBytes(chunkLength)} at byte ${offset} runs past the end of the file (${formatBytes(length)}).`,
      );
    }
    if (json === null) {
      if (type !== CHUNK_JSON) throw new ModelError(`"${name}": a GLB's first chunk must be its JSON.`);
      json = parseJson(
        name,
        decodeText(name, new Uint8Array(bytes, offset + 8, chunkLength), 'its JSON chunk'),
      );
    }
    offset = end;
  }
  if (json === null) throw new ModelError(`"${name}" has no JSON chunk.`);
  return { data: bytes, json, decoders: checkJson(name, json) };
}

function decodeText(name: string, bytes: Uint8Array, what: string): string {
  try {
    return new TextDecoder('utf-8', { fatal: true }).decode(bytes);
  } catch {
    throw new ModelError(`"${name}": ${what} is not UTF-8 text.`);
  }
}

function parseJson(name: string, text: string): GltfJson {
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch (error) {
    throw new ModelError(`"${name}": its JSON is malformed (${(error as Error).message}).`);
  }
  if (typeof value !== 'object' || value === null || Array.isArray(value))
    throw new ModelError(`"${name}": its JSON is not an object.`);
  return value as GltfJson;
}

const list = (value: unknown): unknown[] => (Array.isArray(value) ? value : []);
const record = (value: unknown): Record<string, unknown> =>
  typeof value === 'object' && value !== null ? (value as Record<string, unknown>) : {};

/**
 * The JSON's extensions and embedded resources (what the validator does not check: it reads any extension it
 * knows, and an external file only when it is given a loader); returns the decoders the file needs.
 */
function checkJson(name: string, json: GltfJson): CheckedModel['decoders'] {
  const used = list(json.extensionsUsed).map(String);
  const required = list(json.extensionsRequired).map(String);
  for (const extension of required) {
    if (!SUPPORTED_EXTENSIONS.includes(extension))
      throw new ModelError(
        `"${name}" needs the extension ${extension}, which three's GLTFLoader does not read.`,
      );
  }
  list(json.buffers).forEach((buffer, i) => {
    const { uri } = record(buffer);
    if (uri !== undefined) checkUri(name, uri, `buffer ${i}`);
  });
  list(json.images).forEach((image, i) => {
    const { uri } = record(image);
    if (uri !== undefined) checkUri(name, uri, `image ${i}`);
  });
  const uses = (extension: string) => used.includes(extension) || required.includes(extension);
  return {
    meshopt: MESHOPT_EXTENSIONS.some(uses),
    draco: uses(DRACO_EXTENSION),
    ktx2: uses(KTX2_EXTENSION),
  };
}

/** Only data: URIs: anything else is a file the browser was not given. */
function checkUri(name: string, uri: unknown, what: string): void {
  if (typeof uri !== 'string') throw new ModelError(`"${name}": ${what}'s uri is not text.`);
  if (!uri.startsWith('data:')) {
    const shown = uri.length > 80 ? `${uri.slice(0, 80)}…` : uri;
    throw new ModelError(
      `"${name}": ${what} refers to the external file "${shown}"; only embedded resources are read (a .glb, or a .gltf whose buffers and images are data: URIs).`,
    );
  }
}
