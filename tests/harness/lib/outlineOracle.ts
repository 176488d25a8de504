// The oracle of the outline harnesses (outline-impostor.ts for OutlineMaterial on WebGLRenderer, webgpu-outline.ts
// for OutlineNodeMaterial on WebGPURenderer): the outlined objects, the inverted hull built on the CPU from three's
// own deformation, and the comparison of two pictures by class (clear, outline, mesh).
import {
  BackSide,
  BufferAttribute,
  BufferGeometry,
  Euler,
  InstancedMesh,
  type Material,
  Matrix3,
  Matrix4,
  Mesh,
  Quaternion,
  SkinnedMesh,
  SphereGeometry,
  Vector3,
} from 'three';
import { bindTwoBones, deformNormal, instanceSkinned, skinnedCylinder, stretchMorph } from './deform';
import { hasRgb } from './pixels';

/** The clear colour in RGB: where nothing was drawn. */
export const CLEAR = [0, 0, 255] as const;

/** One instance: position, Euler rotation, scale. */
export interface Instance {
  position: readonly [number, number, number];
  rotation?: readonly [number, number, number];
  scale?: readonly [number, number, number];
  /** instanceColor (linear). */
  color?: readonly [number, number, number];
}

export function instanceMatrix(instance: Instance): Matrix4 {
  return new Matrix4().compose(
    new Vector3(...instance.position),
    new Quaternion().setFromEuler(new Euler(...(instance.rotation ?? [0, 0, 0]))),
    new Vector3(...(instance.scale ?? [1, 1, 1])),
  );
}

/** What is outlined. 'sphere' is a sphere without normals flagged `userData.isSphere` (normal = position). */
export type OutlineObject =
  | 'mesh'
  | 'sphere'
  | 'skinned'
  | 'morphed'
  | 'instanced'
  | 'instanced-morphed'
  | 'instanced-skinned';

export interface OutlineConfig {
  object: OutlineObject;
  /** Outline width, world units. */
  thickness: number;
  /** The skinned cylinder's second bone about z, radians. @default 0.9 */
  bone?: number;
  instances?: readonly Instance[];
  size?: number;
}

/** The geometries of the outlined objects. */
export interface OutlineGeometries {
  sphere: BufferGeometry;
  /** The sphere without normals, flagged `userData.isSphere`. */
  analytic: BufferGeometry;
  morphed: BufferGeometry;
  cylinder: BufferGeometry;
}

/**
 * The geometries, made once per renderer: pictures compared with each other draw the same vertices, and a skinned
 * geometry drawn by WebGPURenderer is not drawn by WebGLRenderer afterwards.
 */
export function outlineGeometries(): OutlineGeometries {
  const analytic = new SphereGeometry(1, 48, 24);
  analytic.deleteAttribute('normal');
  analytic.userData.isSphere = true;
  return {
    sphere: new SphereGeometry(1, 48, 24),
    analytic,
    morphed: stretchMorph(new SphereGeometry(1, 48, 24)),
    cylinder: skinnedCylinder(0.5, 24, 12),
  };
}

/** The outlined object (its body drawn with `body`) and its instance matrices (one identity when not instanced). */
export function outlinedObject(
  config: OutlineConfig,
  body: Material,
  geometries: OutlineGeometries,
): { object: Mesh; matrices: Matrix4[] } {
  const specs = config.instances ?? [{ position: [0, 0, 0] }];
  let matrices = [new Matrix4()];
  if (config.object === 'skinned' || config.object === 'instanced-skinned') {
    const mesh = new SkinnedMesh(geometries.cylinder, body);
    bindTwoBones(mesh, config.bone ?? 0.9);
    mesh.rotation.y = 0.3;
    if (config.object === 'instanced-skinned') {
      matrices = specs.map(instanceMatrix);
      instanceSkinned(mesh, matrices);
      mesh.frustumCulled = false;
    }
    return { object: mesh, matrices };
  }
  if (config.object === 'morphed') {
    const mesh = new Mesh(geometries.morphed, body);
    mesh.morphTargetInfluences = [1];
    mesh.rotation.set(0.2, 0.4, 0);
    return { object: mesh, matrices };
  }
  if (config.object === 'instanced' || config.object === 'instanced-morphed') {
    const morphed = config.object === 'instanced-morphed';
    const mesh = new InstancedMesh(morphed ? geometries.morphed : geometries.sphere, body, specs.length);
    matrices = specs.map(instanceMatrix);
    matrices.forEach((m, i) => {
      mesh.setMatrixAt(i, m);
    });
    if (morphed) {
      mesh.morphTargetInfluences = [1];
      for (let i = 0; i < specs.length; i++) mesh.setMorphAt(i, mesh);
      if (mesh.morphTexture) mesh.morphTexture.needsUpdate = true;
    }
    mesh.scale.set(1.1, 1, 1);
    mesh.frustumCulled = false;
    return { object: mesh, matrices };
  }
  const mesh = new Mesh(config.object === 'sphere' ? geometries.analytic : geometries.sphere, body);
  mesh.scale.set(1.5, 1, 1.5);
  return { object: mesh, matrices };
}

/** The object-space normal of `vertex` as three's vertex stage moves it (morph normals, then the skin matrix). */
function deformedNormal(object: Mesh, vertex: number, deformed: boolean, target: Vector3): Vector3 {
  const geometry = object.geometry;
  // A flagged sphere without normals: normal = position.
  target.fromBufferAttribute(geometry.getAttribute('normal') ?? geometry.getAttribute('position'), vertex);
  if (!deformed) return target;
  return deformNormal(object, geometry, vertex, target);
}

/**
 * The inverted hull on the CPU, in world space: each vertex of each instance, deformed as three deforms it
 * (`getVertexPosition`: morph targets, then bones), through the instance and object matrices, pushed out by
 * `thickness` along its unit world normal (the inverse transpose of each matrix). `deformed: false` builds the
 * hull of the raw geometry at the object's origin (what the outline drew before it followed the mesh). Drawn
 * with `material` (three's black MeshBasicMaterial or MeshBasicNodeMaterial, back faces).
 */
export function cpuHull(
  object: Mesh,
  matrices: Matrix4[],
  thickness: number,
  deformed: boolean,
  material: Material,
): Mesh {
  const geometry = object.geometry;
  const count = geometry.getAttribute('position').count;
  const out = new Float32Array(3 * count * matrices.length);
  const p = new Vector3();
  const n = new Vector3();
  const objectNormal = new Matrix3().getNormalMatrix(object.matrixWorld);
  const index: number[] = [];
  const source = geometry.index;
  matrices.forEach((instance, k) => {
    const instanceNormal = new Matrix3().getNormalMatrix(instance);
    for (let i = 0; i < count; i++) {
      if (deformed) object.getVertexPosition(i, p);
      else p.fromBufferAttribute(geometry.getAttribute('position'), i);
      deformedNormal(object, i, deformed, n);
      p.applyMatrix4(instance).applyMatrix4(object.matrixWorld);
      n.applyMatrix3(instanceNormal).applyMatrix3(objectNormal).normalize();
      p.addScaledVector(n, thickness);
      p.toArray(out, 3 * (k * count + i));
    }
    if (source !== null) for (let j = 0; j < source.count; j++) index.push(k * count + source.getX(j));
  });
  const hull = new BufferGeometry();
  hull.setAttribute('position', new BufferAttribute(out, 3));
  if (source !== null) hull.setIndex(index);
  material.side = BackSide;
  const mesh = new Mesh(hull, material);
  mesh.frustumCulled = false;
  return mesh;
}

/** The pixel classes: 0 clear (the blue background), 1 the outline (black), 2 the mesh (red), 3 anything else. */
export function classify(p: Uint8Array, i: number): number {
  if (hasRgb(p, 4 * i, CLEAR)) return 0;
  if (hasRgb(p, 4 * i, [0, 0, 0])) return 1;
  if (hasRgb(p, 4 * i, [255, 0, 0])) return 2;
  return 3;
}

/** Our picture against a reference: pixels away from the reference's class edges, and how many differ. */
export function compareClasses(ours: Uint8Array, theirs: Uint8Array, size: number): [number, number] {
  let compared = 0;
  let mismatches = 0;
  for (let y = 1; y < size - 1; y++) {
    for (let x = 1; x < size - 1; x++) {
      const i = y * size + x;
      const c = classify(theirs, i);
      let uniform = true;
      for (let dy = -1; uniform && dy <= 1; dy++)
        for (let dx = -1; uniform && dx <= 1; dx++)
          if (classify(theirs, i + dy * size + dx) !== c) uniform = false;
      if (!uniform) continue;
      compared++;
      if (classify(ours, i) !== c) mismatches++;
    }
  }
  return [compared, mismatches];
}
