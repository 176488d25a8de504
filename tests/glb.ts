// A binary glTF (GLB) of one three.js geometry, written in node (three's GLTFExporter needs the DOM's FileReader
// for binary output): one mesh with POSITION, NORMAL and indices, and one metal-rough material, as glTF 2.0
// lays them out (a JSON chunk and a BIN chunk, each padded to 4 bytes). Served by tests that load a model file
// (snippets.spec.ts: the existing-scene guide's example).
import type { BufferGeometry } from 'three';

/** glTF's pbrMetallicRoughness of the one material. */
export interface GlbMaterial {
  /** Linear RGBA. */
  baseColorFactor: [number, number, number, number];
  metallicFactor: number;
  roughnessFactor: number;
}

const FLOAT = 5126;
const UNSIGNED_SHORT = 5123;
const UNSIGNED_INT = 5125;
const ARRAY_BUFFER = 34962;
const ELEMENT_ARRAY_BUFFER = 34963;

/** The GLB bytes of `geometry` (indexed, with position and normal attributes) with `material`. */
export function glbOf(geometry: BufferGeometry, material: GlbMaterial): Buffer {
  const position = geometry.getAttribute('position');
  const normal = geometry.getAttribute('normal');
  const index = geometry.getIndex();
  if (!position || !normal || !index)
    throw new TypeError('glbOf: geometry needs position, normal and an index');
  const positions = Float32Array.from(position.array as ArrayLike<number>);
  const normals = Float32Array.from(normal.array as ArrayLike<number>);
  const wide = position.count > 65535;
  const indices = wide
    ? Uint32Array.from(index.array as ArrayLike<number>)
    : Uint16Array.from(index.array as ArrayLike<number>);

  const views: Buffer[] = [];
  let offset = 0;
  const bufferViews: object[] = [];
  const add = (data: ArrayBufferView, target: number) => {
    const bytes = Buffer.from(data.buffer, data.byteOffset, data.byteLength);
    const padded = Buffer.concat([bytes, Buffer.alloc((4 - (bytes.length % 4)) % 4)]);
    bufferViews.push({ buffer: 0, byteOffset: offset, byteLength: bytes.length, target });
    views.push(padded);
    offset += padded.length;
    return bufferViews.length - 1;
  };
  const min = [0, 1, 2].map((k) => Math.min(...positions.filter((_, i) => i % 3 === k)));
  const max = [0, 1, 2].map((k) => Math.max(...positions.filter((_, i) => i % 3 === k)));
  const json = {
    asset: { version: '2.0', generator: 'shadelab tests/glb.ts' },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0, name: 'model' }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0, NORMAL: 1 }, indices: 2, material: 0 }] }],
    materials: [{ name: 'surface', pbrMetallicRoughness: material }],
    accessors: [
      {
        bufferView: add(positions, ARRAY_BUFFER),
        componentType: FLOAT,
        count: position.count,
        type: 'VEC3',
        min,
        max,
      },
      { bufferView: add(normals, ARRAY_BUFFER), componentType: FLOAT, count: normal.count, type: 'VEC3' },
      {
        bufferView: add(indices, ELEMENT_ARRAY_BUFFER),
        componentType: wide ? UNSIGNED_INT : UNSIGNED_SHORT,
        count: indices.length,
        type: 'SCALAR',
      },
    ],
    bufferViews,
    buffers: [{ byteLength: offset }],
  };
  const text = Buffer.from(JSON.stringify(json), 'utf8');
  const jsonChunk = Buffer.concat([text, Buffer.alloc((4 - (text.length % 4)) % 4, 0x20)]);
  const binChunk = Buffer.concat(views);
  const header = Buffer.alloc(12);
  header.writeUInt32LE(0x46546c67, 0); // 'glTF'
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + jsonChunk.length + 8 + binChunk.length, 8);
  const chunk = (type: number, body: Buffer) => {
    const head = Buffer.alloc(8);
    head.writeUInt32LE(body.length, 0);
    head.writeUInt32LE(type, 4);
    return Buffer.concat([head, body]);
  };
  return Buffer.concat([header, chunk(0x4e4f534a, jsonChunk), chunk(0x004e4942, binChunk)]);
}
