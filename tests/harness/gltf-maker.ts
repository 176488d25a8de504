// Harness for tests/playground-model.spec.ts (issue 22): the glTF models the playground is given, built in code
// and exported with three's GLTFExporter (binary GLB, nothing downloaded), as a user's tool would write them.
// `window.makeModel(kind)` resolves to the GLB's bytes (an array of numbers, to cross into the test).
import {
  AnimationClip,
  Bone,
  BoxGeometry,
  DataTexture,
  Float32BufferAttribute,
  Group,
  IcosahedronGeometry,
  Mesh,
  MeshStandardMaterial,
  Points,
  PointsMaterial,
  Quaternion,
  QuaternionKeyframeTrack,
  RGBAFormat,
  Scene,
  Skeleton,
  SkinnedMesh,
  SRGBColorSpace,
  TorusKnotGeometry,
  Vector3,
} from 'three';
import { GLTFExporter } from 'three/addons/exporters/GLTFExporter.js';
import { skinnedCylinder } from './lib/deform';

/**
 * The models: a textured box (and a Points cloud, which the swap leaves), a vertex-coloured ball, a skinned
 * cylinder bent by its clip, and a torus knot and a box in plain colours (one of them emissive).
 */
export type ModelKind = 'textured' | 'vertexColours' | 'skinned' | 'coloured';

declare global {
  interface Window {
    makeModel(kind: ModelKind): Promise<number[]>;
  }
}

/** An 8 × 8 checker of two colours (sRGB), RGBA. */
function checker(): DataTexture {
  const size = 8;
  const data = new Uint8Array(size * size * 4);
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const on = (x + y) % 2 === 0;
      data.set(on ? [230, 200, 60, 255] : [40, 120, 200, 255], 4 * (y * size + x));
    }
  }
  const texture = new DataTexture(data, size, size, RGBAFormat);
  texture.colorSpace = SRGBColorSpace;
  texture.needsUpdate = true;
  return texture;
}

function textured(scene: Scene): undefined {
  const box = new Mesh(
    new BoxGeometry(1.6, 1, 1.2),
    new MeshStandardMaterial({ map: checker(), roughness: 0.6, metalness: 0 }),
  );
  box.name = 'textured box';
  box.rotation.set(0.5, 0.7, 0);
  scene.add(box);
  // A small cloud of points beside it: glTF points, which the swap leaves as they are.
  const points = new Points(
    undefined,
    new PointsMaterial({ color: 0xffffff, size: 2, sizeAttenuation: false }),
  );
  points.geometry.setAttribute(
    'position',
    new Float32BufferAttribute([1.1, 0.6, 0, 1.2, 0.7, 0.1, 1.0, 0.75, -0.1], 3),
  );
  points.name = 'points';
  scene.add(points);
}

function vertexColours(scene: Scene): undefined {
  const geometry = new IcosahedronGeometry(1, 3);
  const position = geometry.getAttribute('position');
  const colours: number[] = [];
  for (let i = 0; i < position.count; i++) {
    colours.push(0.5 + 0.5 * position.getX(i), 0.5 + 0.5 * position.getY(i), 0.5 + 0.5 * position.getZ(i));
  }
  geometry.setAttribute('color', new Float32BufferAttribute(colours, 3));
  const mesh = new Mesh(geometry, new MeshStandardMaterial({ vertexColors: true, roughness: 0.5 }));
  mesh.name = 'vertex-coloured ball';
  mesh.scale.set(1.4, 1, 1);
  scene.add(mesh);
}

function coloured(scene: Scene): undefined {
  const knot = new Mesh(
    new TorusKnotGeometry(0.6, 0.2, 96, 12),
    new MeshStandardMaterial({ color: 0x3080e0, roughness: 0.4, metalness: 0.2 }),
  );
  knot.name = 'torus knot';
  knot.position.x = -0.9;
  const box = new Mesh(
    new BoxGeometry(1, 1, 1),
    new MeshStandardMaterial({ color: 0xe04040, roughness: 0.7, emissive: 0x202000 }),
  );
  box.name = 'box';
  box.position.x = 0.9;
  box.rotation.set(0.4, 0.6, 0);
  scene.add(knot, box);
}

/** The skinned cylinder (bones at y = −1.5 and 0) and a 2 s clip that bends it one way and back. */
function skinned(scene: Scene): AnimationClip[] {
  const mesh = new SkinnedMesh(skinnedCylinder(0.45, 24, 16), new MeshStandardMaterial({ color: 0xd08050 }));
  mesh.name = 'skinned cylinder';
  const root = new Bone();
  root.name = 'root';
  root.position.y = -1.5;
  const bend = new Bone();
  bend.name = 'bend';
  bend.position.y = 1.5;
  root.add(bend);
  mesh.add(root);
  const group = new Group();
  group.add(mesh);
  scene.add(group);
  mesh.bind(new Skeleton([root, bend]));
  const turn = (angle: number) => new Quaternion().setFromAxisAngle(new Vector3(0, 0, 1), angle).toArray();
  const track = new QuaternionKeyframeTrack(
    'bend.quaternion',
    [0, 1, 2],
    [...turn(0), ...turn(1.2), ...turn(0)],
  );
  return [new AnimationClip('bend', 2, [track])];
}

window.makeModel = async (kind) => {
  const scene = new Scene();
  const builders = { textured, vertexColours, skinned, coloured } as const;
  const animations = builders[kind](scene) ?? [];
  const glb = (await new GLTFExporter().parseAsync(scene, { binary: true, animations })) as ArrayBuffer;
  return Array.from(new Uint8Array(glb));
};
