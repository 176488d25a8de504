import { validateBytes } from 'gltf-validator';
import { describe, expect, it } from 'vitest';
import { type CheckedModel, checkModelBytes, formatBytes, MODEL_MAX_BYTES, ModelError } from './gltfCheck';
import { DRAWN_ANYWAY, validateModel } from './gltfValidate';

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

/** The message of the validator's refusal of a file that passes the hand checks. */
const invalid = async (bytes: ArrayBuffer, name = 'm.glb') => {
  const checked: CheckedModel = checkModelBytes(name, bytes);
  const error = await validateModel(name, checked).then(
    () => null,
    (e: unknown) => e,
  );
  expect(error).toBeInstanceOf(ModelError);
  return (error as Error).message;
};

describe('checkModelBytes', () => {
  it('takes a GLB and a .gltf with a data: buffer, and says which decoders it needs', async () => {
    const ok = checkModelBytes('m.glb', glb(GOOD, new Uint8Array(8)));
    expect(ok.decoders).toEqual({ meshopt: false, draco: false, ktx2: false });
    expect(ok.data).toBeInstanceOf(ArrayBuffer);
    await validateModel('m.glb', ok);
    const text = JSON.stringify({
      ...GOOD,
      buffers: [{ byteLength: 8, uri: `data:application/octet-stream;base64,${btoa('12345678')}` }],
    });
    const gltf = checkModelBytes('m.gltf', new TextEncoder().encode(`\ufeff \n${text}`).buffer);
    expect(typeof gltf.data).toBe('string');
    await validateModel('m.gltf', gltf);
    const meshopt = { ...GOOD, extensionsUsed: ['EXT_meshopt_compression'] };
    expect(checkModelBytes('m.glb', glb(meshopt, new Uint8Array(8))).decoders.meshopt).toBe(true);
    // Draco meshes and KTX2 textures, required or only used: their decoders are loaded for the file.
    for (const [extension, decoder] of [
      ['KHR_draco_mesh_compression', 'draco'],
      ['KHR_texture_basisu', 'ktx2'],
    ] as const) {
      const json = { ...GOOD, extensionsUsed: [extension], extensionsRequired: [extension] };
      expect(checkModelBytes('m.glb', glb(json, new Uint8Array(8))).decoders[decoder]).toBe(true);
      const used = { ...GOOD, extensionsUsed: [extension] };
      expect(checkModelBytes('m.glb', glb(used, new Uint8Array(8))).decoders[decoder]).toBe(true);
    }
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
    expect(refused(new Uint8Array(0).buffer)).toBe('"m.glb" is empty.');
  });

  it('refuses external references and extensions three does not read, naming them', () => {
    const external = { ...GOOD, buffers: [{ byteLength: 8, uri: 'm.bin' }] };
    expect(refused(glb(external))).toMatch(/buffer 0 refers to the external file "m.bin"/);
    const image = { ...GOOD, images: [{ uri: 'https://example.invalid/t.png' }] };
    expect(refused(glb(image, new Uint8Array(8)))).toMatch(/image 0 refers to the external file/);
    const unknown = { ...GOOD, extensionsUsed: ['X_y'], extensionsRequired: ['X_y'] };
    expect(refused(glb(unknown, new Uint8Array(8)))).toMatch(
      /needs the extension X_y, which three's GLTFLoader/,
    );
  });

  it('measures sizes', () => {
    expect(formatBytes(MODEL_MAX_BYTES)).toBe('64 MiB');
    expect(formatBytes(1234)).toBe('1,234 bytes');
  });
});

describe('validateModel (the Khronos glTF Validator)', () => {
  it('refuses missing buffers, short buffers and data: URIs, and missing views, naming the error and where it is', async () => {
    expect(await invalid(glb(GOOD))).toBe(
      '"m.glb" is not valid glTF: the Khronos glTF Validator found an error: /buffers/0: Buffer refers to an unresolved GLB binary chunk.',
    );
    expect(await invalid(glb(GOOD, new Uint8Array(4)))).toMatch(/^"m.glb" is not valid glTF: .*\/buffers\/0/);
    const short = {
      ...GOOD,
      buffers: [{ byteLength: 8, uri: `data:application/octet-stream;base64,${btoa('abcde')}` }],
    };
    expect(await invalid(new TextEncoder().encode(JSON.stringify(short)).buffer, 'm.gltf')).toMatch(
      /\/buffers\/0: Actual data byte length \(5\) is less than the declared buffer byte length \(8\)/,
    );
    expect(
      await invalid(glb({ ...GOOD, bufferViews: [{ buffer: 3, byteLength: 8 }] }, new Uint8Array(8))),
    ).toMatch(/\/bufferViews\/0\/buffer: Unresolved reference: 3/);
    expect(
      await invalid(
        glb({ ...GOOD, accessors: [{ ...GOOD.accessors[0], bufferView: 2 }] }, new Uint8Array(8)),
      ),
    ).toMatch(/\/accessors\/0\/bufferView: Unresolved reference: 2/);
    expect(await invalid(glb({ ...GOOD, images: [{}] }, new Uint8Array(8)))).toMatch(
      /\/images\/0: Exactly one of \('bufferView', 'uri'\) properties must be defined/,
    );
    expect(await invalid(new TextEncoder().encode('{"x":1}').buffer, 'a.gltf')).toMatch(
      /^"a.gltf" is not valid glTF: .*Property 'asset' must be defined/,
    );
  });

  it('counts the errors and shows the first three', async () => {
    const json = { ...GOOD, bufferViews: [0, 1, 2, 3].map((i) => ({ buffer: 5 + i, byteLength: 8 })) };
    const message = await invalid(glb(json, new Uint8Array(8)));
    expect(message).toMatch(/found (\d+) errors: /);
    expect(message.split('Unresolved reference').length - 1).toBe(3);
    expect(message).toMatch(/; …$/);
  });

  it('takes the value errors three draws anyway (bounds that do not match), refuses the others (an index out of range)', async () => {
    const positions = new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    const triangle = (max: number[], index: number) => {
      const bin = new Uint8Array(44);
      bin.set(new Uint8Array(positions.buffer), 0);
      bin.set(new Uint8Array(new Uint16Array([0, 1, index]).buffer), 36);
      return glb(
        {
          asset: { version: '2.0' },
          scene: 0,
          scenes: [{ nodes: [0] }],
          nodes: [{ mesh: 0 }],
          meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1 }] }],
          buffers: [{ byteLength: 44 }],
          bufferViews: [
            { buffer: 0, byteOffset: 0, byteLength: 36, target: 34962 },
            { buffer: 0, byteOffset: 36, byteLength: 6, target: 34963 },
          ],
          accessors: [
            { bufferView: 0, componentType: 5126, count: 3, type: 'VEC3', min: [0, 0, 0], max },
            { bufferView: 1, componentType: 5123, count: 3, type: 'SCALAR' },
          ],
        },
        bin,
      );
    };
    const exact = checkModelBytes('t.glb', triangle([1, 1, 0], 2));
    await validateModel('t.glb', exact);
    // The declared maximum is off: an error for the validator, drawn as it is by three.
    const off = triangle([1.5, 1, 0], 2);
    const report = await validateBytes(new Uint8Array(off), { writeTimestamp: false });
    expect(report.issues.messages.filter((m) => m.severity === 0).map((m) => m.code)).toEqual([
      'ACCESSOR_MAX_MISMATCH',
    ]);
    expect(DRAWN_ANYWAY).toContain('ACCESSOR_MAX_MISMATCH');
    await validateModel('t.glb', checkModelBytes('t.glb', off));
    expect(await invalid(triangle([1, 1, 0], 7), 't.glb')).toMatch(
      /\/meshes\/0\/primitives\/0\/indices: Indices accessor element at index 2 has value 7 that is greater than the maximum vertex index available \(2\)/,
    );
  });
});
