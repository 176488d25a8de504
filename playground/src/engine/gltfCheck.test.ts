import { describe, expect, it } from 'vitest';
import { checkModelBytes, dataUriBytes, formatBytes, MODEL_MAX_BYTES, ModelError } from './gltfCheck';

/** A GLB from a JSON object and an optional binary chunk (each padded to 4 bytes), as the spec lays it out. */
function glb(json: object, bin: Uint8Array | null = null, version = 2): ArrayBuffer {
  const text = new TextEncoder().encode(JSON.stringify(json));
  const jsonLength = Math.ceil(text.length / 4) * 4;
  const binLength = bin ? Math.ceil(bin.length / 4) * 4 : 0;
  const length = 12 + 8 + jsonLength + (bin ? 8 + binLength : 0);
  const bytes = new Uint8Array(length);
  const view = new DataView(bytes.buffer);
  view.setUint32(0, 0x46546c67, true);
  view.setUint32(4, version, true);
  view.setUint32(8, length, true);
  view.setUint32(12, jsonLength, true);
  view.setUint32(16, 0x4e4f534a, true);
  bytes.fill(0x20, 20, 20 + jsonLength);
  bytes.set(text, 20);
  if (bin) {
    view.setUint32(20 + jsonLength, binLength, true);
    view.setUint32(24 + jsonLength, 0x004e4942, true);
    bytes.set(bin, 28 + jsonLength);
  }
  return bytes.buffer;
}

const GOOD = {
  asset: { version: '2.0' },
  buffers: [{ byteLength: 8 }],
  bufferViews: [{ buffer: 0, byteOffset: 0, byteLength: 8 }],
  accessors: [{ bufferView: 0, componentType: 5126, count: 2, type: 'SCALAR' }],
};

const refused = (bytes: ArrayBuffer, name = 'm.glb') => {
  try {
    checkModelBytes(name, bytes);
  } catch (error) {
    expect(error).toBeInstanceOf(ModelError);
    return (error as Error).message;
  }
  throw new Error('not refused');
};

describe('checkModelBytes', () => {
  it('takes a GLB and a .gltf with a data: buffer, and says when meshopt is used', () => {
    const ok = checkModelBytes('m.glb', glb(GOOD, new Uint8Array(8)));
    expect(ok.meshopt).toBe(false);
    expect(ok.data).toBeInstanceOf(ArrayBuffer);
    const text = JSON.stringify({
      ...GOOD,
      buffers: [{ byteLength: 8, uri: `data:;base64,${btoa('12345678')}` }],
    });
    const gltf = checkModelBytes('m.gltf', new TextEncoder().encode(`\ufeff \n${text}`).buffer);
    expect(typeof gltf.data).toBe('string');
    const meshopt = { ...GOOD, extensionsUsed: ['EXT_meshopt_compression'] };
    expect(checkModelBytes('m.glb', glb(meshopt, new Uint8Array(8))).meshopt).toBe(true);
  });

  it('refuses a GLB whose header claims more than the limit, before reading further', () => {
    const bytes = glb(GOOD, new Uint8Array(8));
    new DataView(bytes).setUint32(8, 2 ** 31, true);
    expect(refused(bytes)).toBe(
      `"m.glb": its GLB header claims 2.0 GiB, more than the playground's limit of 64 MiB; refused before reading it.`,
    );
  });

  it('refuses truncated, wrong-magic, wrong-version and chunk-overrunning files', () => {
    const good = glb(GOOD, new Uint8Array(8));
    expect(refused(good.slice(0, good.byteLength - 4))).toMatch(/is truncated: its GLB header says/);
    expect(refused(good.slice(0, 8))).toMatch(/shorter than a GLB header/);
    expect(refused(glb(GOOD, null, 1))).toMatch(/GLB of version 1/);
    const overrun = glb(GOOD, new Uint8Array(8));
    new DataView(overrun).setUint32(12, 10_000, true);
    expect(refused(overrun)).toMatch(/runs past the end of the file/);
    expect(refused(new Uint8Array([0x89, 0x50, 0x4e, 0x47, 1, 2]).buffer, 'p.png')).toBe(
      '"p.png" is not a glTF file: it starts with the bytes 89 50 4e 47, neither a GLB\'s magic "glTF" nor JSON text.',
    );
    expect(refused(new TextEncoder().encode('{"asset":').buffer, 'a.gltf')).toMatch(/its JSON is malformed/);
    expect(refused(new TextEncoder().encode('{"x":1}').buffer, 'a.gltf')).toMatch(/no asset.version/);
    expect(refused(new Uint8Array(0).buffer)).toBe('"m.glb" is empty.');
  });

  it('refuses missing buffers and views, external references and undecodable extensions, naming them', () => {
    expect(refused(glb(GOOD))).toMatch(/buffer 0 is missing \(no uri, and the file has no binary chunk\)/);
    expect(refused(glb(GOOD, new Uint8Array(4)))).toMatch(
      /buffer 0 declares 8 bytes, its binary chunk holds 4 bytes/,
    );
    expect(refused(glb({ ...GOOD, bufferViews: [{ buffer: 3, byteLength: 8 }] }, new Uint8Array(8)))).toMatch(
      /bufferView 0 refers to buffer 3, which is missing/,
    );
    expect(refused(glb({ ...GOOD, accessors: [{ bufferView: 2 }] }, new Uint8Array(8)))).toMatch(
      /accessor 0 refers to bufferView 2/,
    );
    const external = { ...GOOD, buffers: [{ byteLength: 8, uri: 'm.bin' }] };
    expect(refused(glb(external))).toMatch(/buffer 0 refers to the external file "m.bin"/);
    const image = { ...GOOD, images: [{ uri: 'https://example.invalid/t.png' }] };
    expect(refused(glb(image, new Uint8Array(8)))).toMatch(/image 0 refers to the external file/);
    for (const extension of ['KHR_draco_mesh_compression', 'KHR_texture_basisu']) {
      const json = { ...GOOD, extensionsUsed: [extension], extensionsRequired: [extension] };
      expect(refused(glb(json, new Uint8Array(8)))).toMatch(
        `needs the extension ${extension}, which the playground`,
      );
    }
    // KTX2 only used (not required): three takes the fallback image.
    expect(() =>
      checkModelBytes('m.glb', glb({ ...GOOD, extensionsUsed: ['KHR_texture_basisu'] }, new Uint8Array(8))),
    ).not.toThrow();
    const unknown = { ...GOOD, extensionsUsed: ['X_y'], extensionsRequired: ['X_y'] };
    expect(refused(glb(unknown, new Uint8Array(8)))).toMatch(
      /needs the extension X_y, which three's GLTFLoader/,
    );
  });

  it('measures data: URIs and sizes', () => {
    expect(dataUriBytes(`data:application/octet-stream;base64,${btoa('abcde')}`)).toBe(5);
    expect(dataUriBytes('data:,abc%20d')).toBe(5);
    expect(dataUriBytes('m.bin')).toBeNull();
    expect(formatBytes(MODEL_MAX_BYTES)).toBe('64 MiB');
    expect(formatBytes(1234)).toBe('1,234 bytes');
  });
});
