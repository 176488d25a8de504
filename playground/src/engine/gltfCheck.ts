/**
 * What the playground checks in a user's glTF file before three's GLTFLoader sees it: its size, its container
 * (a GLB's header and chunks, or JSON text), and that everything it refers to is inside the file and decodable
 * here. Each refusal is a {@link ModelError} whose message the page shows as it is. Pure (no three, no DOM):
 * unit-tested in gltfCheck.test.ts.
 */

/** Largest file the playground reads, bytes (64 MiB); a GLB header claiming more is refused before parsing. */
export const MODEL_MAX_BYTES = 64 * 1024 * 1024;

/** A file refused: the message names the file and what is wrong with it (shown in the page). */
export class ModelError extends Error {
  override name = 'ModelError';
}

/** The parts of a glTF's JSON the checks read (everything else is three's GLTFLoader's). */
export interface GltfJson {
  asset?: { version?: unknown };
  extensionsUsed?: unknown;
  extensionsRequired?: unknown;
  buffers?: unknown;
  bufferViews?: unknown;
  images?: unknown;
  accessors?: unknown;
  [key: string]: unknown;
}

/** A file that passed the checks. */
export interface CheckedModel {
  /** What `GLTFLoader.parse` takes: the GLB's bytes, or the .gltf's text. */
  readonly data: ArrayBuffer | string;
  readonly json: GltfJson;
  /** The file compresses buffer views with meshopt (the decoder is loaded for it). */
  readonly meshopt: boolean;
}

/** Extensions that need a decoder the playground does not ship (playground README, "Your model"). */
export const REFUSED_EXTENSIONS: Readonly<Record<string, string>> = {
  KHR_draco_mesh_compression: 'DRACO mesh compression needs the DRACO decoder (WebAssembly)',
  KHR_texture_basisu: 'KTX2/Basis textures need the Basis transcoder (WebAssembly)',
};
/** The meshopt extensions: decoded by three's pure-JS `meshopt_decoder.module.js`, loaded when a file uses one. */
export const MESHOPT_EXTENSIONS = ['EXT_meshopt_compression', 'KHR_meshopt_compression'] as const;
/** The extensions three r187's GLTFLoader reads without a decoder (a required one outside these is refused). */
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
  ...MESHOPT_EXTENSIONS,
];

const GLB_MAGIC = 0x46546c67; // 'glTF', little-endian
const CHUNK_JSON = 0x4e4f534a; // 'JSON'
const CHUNK_BIN = 0x004e4942; // 'BIN\0'

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
  return { data: text, json, meshopt: checkJson(name, json, null) };
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
  let bin: number | null = null;
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
    } else if (type === CHUNK_BIN && bin === null) {
      bin = chunkLength;
    }
    offset = end;
  }
  if (json === null) throw new ModelError(`"${name}" has no JSON chunk.`);
  return { data: bytes, json, meshopt: checkJson(name, json, bin) };
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
const isIndex = (value: unknown, length: number) =>
  typeof value === 'number' && Number.isInteger(value) && value >= 0 && value < length;

/** Bytes a data: URI holds (base64 or percent-encoded); null when it is not one. */
export function dataUriBytes(uri: string): number | null {
  const comma = uri.indexOf(',');
  if (!uri.startsWith('data:') || comma < 0) return null;
  const payload = uri.slice(comma + 1);
  if (!/;base64$/i.test(uri.slice(0, comma))) return decodeURIComponent(payload).length;
  const clean = payload.replace(/\s/g, '');
  return Math.floor((clean.length * 3) / 4) - (clean.endsWith('==') ? 2 : clean.endsWith('=') ? 1 : 0);
}

/** The JSON's references and extensions; returns whether meshopt is used. `bin`: the GLB's BIN chunk length. */
function checkJson(name: string, json: GltfJson, bin: number | null): boolean {
  const version = record(json.asset).version;
  if (typeof version !== 'string') throw new ModelError(`"${name}" has no asset.version: not a glTF.`);
  if (Number.parseInt(version, 10) !== 2)
    throw new ModelError(`"${name}" is glTF ${version}; only glTF 2.x is read.`);
  const used = list(json.extensionsUsed).map(String);
  const required = list(json.extensionsRequired).map(String);
  for (const extension of new Set([...used, ...required])) {
    const why = REFUSED_EXTENSIONS[extension];
    // A KTX2 texture that is only used has a fallback image, which three takes.
    if (why && (extension !== 'KHR_texture_basisu' || required.includes(extension))) {
      throw new ModelError(
        `"${name}" needs the extension ${extension}, which the playground does not decode: ${why}.`,
      );
    }
  }
  for (const extension of required) {
    if (!SUPPORTED_EXTENSIONS.includes(extension))
      throw new ModelError(
        `"${name}" needs the extension ${extension}, which three's GLTFLoader does not read.`,
      );
  }
  const buffers = list(json.buffers).map(record);
  buffers.forEach((buffer, i) => {
    const declared = buffer['byteLength'];
    if (typeof declared !== 'number' || !(declared >= 0))
      throw new ModelError(`"${name}": buffer ${i} has no byteLength.`);
    const extensions = record(buffer['extensions']);
    const fallback = MESHOPT_EXTENSIONS.some((e) => record(extensions[e])['fallback'] === true);
    const uri = buffer['uri'];
    if (uri === undefined) {
      if (fallback) return;
      if (i !== 0 || bin === null) {
        throw new ModelError(
          `"${name}": buffer ${i} is missing (no uri${bin === null ? ', and the file has no binary chunk' : ''}).`,
        );
      }
      if (bin < declared) {
        throw new ModelError(
          `"${name}": buffer 0 declares ${formatBytes(declared)}, its binary chunk holds ${formatBytes(bin)}.`,
        );
      }
      return;
    }
    checkUri(name, uri, `buffer ${i}`);
    const held = dataUriBytes(uri as string);
    if (held !== null && held < declared) {
      throw new ModelError(
        `"${name}": buffer ${i} declares ${formatBytes(declared)}, its data: URI holds ${formatBytes(held)}.`,
      );
    }
  });
  const views = list(json.bufferViews).map(record);
  views.forEach((view, i) => {
    const buffer = view['buffer'];
    if (!isIndex(buffer, buffers.length)) {
      throw new ModelError(
        `"${name}": bufferView ${i} refers to buffer ${String(buffer)}, which is missing (${buffers.length} buffers).`,
      );
    }
    const end = Number(view['byteOffset'] ?? 0) + Number(view['byteLength']);
    if (!(end <= Number(buffers[buffer as number]!['byteLength']))) {
      throw new ModelError(`"${name}": bufferView ${i} runs past the end of buffer ${String(buffer)}.`);
    }
  });
  list(json.accessors).forEach((accessor, i) => {
    const view = record(accessor)['bufferView'];
    if (view !== undefined && !isIndex(view, views.length))
      throw new ModelError(
        `"${name}": accessor ${i} refers to bufferView ${String(view)}, which is missing.`,
      );
  });
  list(json.images).forEach((image, i) => {
    const { uri, bufferView } = record(image);
    if (uri !== undefined) checkUri(name, uri, `image ${i}`);
    else if (!isIndex(bufferView, views.length))
      throw new ModelError(`"${name}": image ${i} has neither a uri nor a bufferView of the file.`);
  });
  return MESHOPT_EXTENSIONS.some((e) => used.includes(e));
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
