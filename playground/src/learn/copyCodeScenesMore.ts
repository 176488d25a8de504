/**
 * Copy as code: the picker's skinned and textured scenes as plain three.js functions (the same numbers as
 * `engine/scenes/skinned.ts` and `textured.ts`), for `copyCodeScenes.ts`.
 */
import { type Imports, outlineEach, type SceneCode } from './copyCodeFormat';
import type { Options } from './copyCodeModel';

/** A cylinder on four bones in a fixed pose, with a morph target that swells it (`engine/scenes/skinned.ts`). */
export function skinned(imports: Imports, flat: boolean, outline: Options | null): SceneCode {
  imports.add('@shadelab/material', 'type ShadingMaterial');
  const geometry = flat
    ? `${imports.add('@shadelab/material', 'flatShadingGeometry')}(geometry)`
    : 'geometry';
  return {
    declaration: `/** A cylinder on a chain of four bones, posed, with a morph target swelling its middle in rings. */
function skinnedCylinder(material: ShadingMaterial): THREE.Group {
  const height = 2.8;
  const segment = height / 3;
  const geometry = new THREE.CylinderGeometry(0.36, 0.36, height, 48, 56, false);
  // Skin: each vertex follows the two bones around its height, weighted linearly between them.
  const position = geometry.getAttribute('position');
  const skinIndex: number[] = [];
  const skinWeight: number[] = [];
  for (let i = 0; i < position.count; i++) {
    const s = Math.min(3 - 1e-6, (position.getY(i) + height / 2) / segment);
    const bone = Math.floor(s);
    skinIndex.push(bone, bone + 1, 0, 0);
    skinWeight.push(1 - (s - bone), s - bone, 0, 0);
  }
  geometry.setAttribute('skinIndex', new THREE.Uint16BufferAttribute(skinIndex, 4));
  geometry.setAttribute('skinWeight', new THREE.Float32BufferAttribute(skinWeight, 4));
  // The morph target: swollen in the middle, with rings (positions and their normals).
  const swollen = geometry.clone();
  const p = swollen.getAttribute('position');
  for (let i = 0; i < p.count; i++) {
    const t = p.getY(i) / height + 0.5;
    const k = 1 + 0.45 * Math.sin(Math.PI * t) ** 2 + 0.1 * Math.sin(8 * Math.PI * t) ** 2;
    p.setXYZ(i, p.getX(i) * k, p.getY(i), p.getZ(i) * k);
  }
  swollen.deleteAttribute('normal');
  swollen.computeVertexNormals();
  geometry.morphAttributes['position'] = [p.clone()];
  geometry.morphAttributes['normal'] = [swollen.getAttribute('normal').clone()];
  const bones: THREE.Bone[] = [];
  for (let b = 0; b < 4; b++) {
    const bone = new THREE.Bone();
    bone.position.y = b === 0 ? -height / 2 : segment;
    bones[b - 1]?.add(bone);
    bones.push(bone);
  }
  const mesh = new THREE.SkinnedMesh(${geometry}, material);
  mesh.add(bones[0]!);
  mesh.bind(new THREE.Skeleton(bones));
  // The pose, after binding (the bind pose is the straight cylinder).
  [0, 0.4, 0.45, 0.35].forEach((bend, b) => {
    bones[b]!.rotation.z = bend;
  });
  bones[3]!.rotation.y = 0.35;
  mesh.morphTargetInfluences = [1];
  mesh.frustumCulled = false; // skinning moves the vertices outside the rest bounds
${outlineEach(imports, '[mesh]', outline)}  const root = new THREE.Group().add(mesh);
  root.position.set(0.45, 0.1, 0);
  return new THREE.Group().add(root);
}`,
    build: (material) => `skinnedCylinder(${material})`,
  };
}

/** A torus knot with a checker map and a bump normal map made in code (`engine/scenes/textured.ts`). */
export function textured(imports: Imports, flat: boolean, outline: Options | null): SceneCode {
  imports.add('@shadelab/material', 'type ShadingMaterial');
  // Flat shading draws the knot as a triangle soup that keeps the uv the textures need.
  const geometry = `new THREE.TorusKnotGeometry(1, 0.36, 200, 24)${flat ? '.toNonIndexed()' : ''}`;
  return {
    declaration: `/** A 64 × 64 texture, each texel's RGBA from \`texel(x, y)\`, repeated 12 × 2 times. */
function texture(texel: (x: number, y: number) => number[], colorSpace: THREE.ColorSpace): THREE.DataTexture {
  const data = new Uint8Array(64 * 64 * 4);
  for (let y = 0; y < 64; y++) for (let x = 0; x < 64; x++) data.set(texel(x, y), 4 * (y * 64 + x));
  const map = new THREE.DataTexture(data, 64, 64);
  map.colorSpace = colorSpace;
  map.wrapS = map.wrapT = THREE.RepeatWrapping;
  map.repeat.set(12, 2);
  map.magFilter = THREE.LinearFilter;
  map.minFilter = THREE.LinearMipmapLinearFilter;
  map.generateMipmaps = true;
  map.needsUpdate = true;
  return map;
}

/** A torus knot with a checker map (it tints ka and kd) and a normal map of round bumps (Phong shading only). */
function texturedKnot(material: ShadingMaterial): THREE.Mesh {
  material.map = texture((x, y) => ((Math.floor(x / 8) + Math.floor(y / 8)) % 2 === 0 ? [235, 235, 225, 255] : [120, 90, 70, 255]), THREE.SRGBColorSpace);
  material.normalMap = texture((x, y) => {
    // Position inside the bump's 16-texel cell, −1 … 1; the height is cos²(π r / 2) inside the unit disc.
    const u = (((x + 0.5) % 16) / 16) * 2 - 1;
    const v = (((y + 0.5) % 16) / 16) * 2 - 1;
    const r = Math.hypot(u, v);
    const dhdr = r < 1 ? -(Math.PI / 2) * Math.sin(Math.PI * r) : 0;
    const dx = r > 0 ? (dhdr * u) / r : 0;
    const dy = r > 0 ? (dhdr * v) / r : 0;
    const n = new THREE.Vector3(-2.5 * dx * (2 / 16), -2.5 * dy * (2 / 16), 1).normalize();
    return [Math.round((n.x * 0.5 + 0.5) * 255), Math.round((n.y * 0.5 + 0.5) * 255), Math.round((n.z * 0.5 + 0.5) * 255), 255];
  }, THREE.NoColorSpace);
  const mesh = new THREE.Mesh(${geometry}, material);
${outlineEach(imports, '[mesh]', outline)}  return mesh;
}`,
    build: (material) => `texturedKnot(${material})`,
  };
}
