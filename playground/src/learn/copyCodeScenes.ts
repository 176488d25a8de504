/**
 * Copy as code: the demo scenes of the picker as plain three.js functions a program can paste (the same numbers
 * as `engine/scenes/`, so the copied program draws the same picture), and a loaded model's code. Both emitters
 * (three.js and R3F) print the same function; the R3F one calls it in a `useMemo`.
 */
import { type Imports, objectLiteral, outlineEach, type SceneCode } from './copyCodeFormat';
import type { Options } from './copyCodeModel';
import { skinned, textured } from './copyCodeScenesMore';

/** `flatShadingGeometry(g)` for flat shading (each face lit once), else `g`. */
function prepared(imports: Imports, flat: boolean, geometry: string): string {
  if (!flat) return geometry;
  imports.add('@shadelab/material', 'flatShadingGeometry');
  return `flatShadingGeometry(${geometry})`;
}

/** The instanced field of spheres (`engine/scenes/instanced.ts`). */
function instanced(imports: Imports, flat: boolean, outline: Options | null): SceneCode {
  imports.add('@shadelab/sphere', 'SubdivisionSphereGeometry');
  imports.add('@shadelab/material', 'type ShadingMaterial');
  const geometry = prepared(
    imports,
    flat,
    "new SubdivisionSphereGeometry({ base: 'icosahedron', level: 3, normals: 'none' })",
  );
  return {
    declaration: `/** 40 spheres in one InstancedMesh, in two layers; each instance's colour tints ka and kd. */
function instancedSpheres(material: ShadingMaterial): THREE.InstancedMesh {
  const spheres = new THREE.InstancedMesh(${geometry}, material, 40);
  const matrix = new THREE.Matrix4();
  const color = new THREE.Color();
  let i = 0;
  for (let layer = 0; layer < 2; layer++) {
    for (let row = 0; row < 4; row++) {
      for (let column = 0; column < 5; column++) {
        // The back layer is shifted by half a cell; sizes, squash, turn and colour follow the index.
        const shift = layer * 0.5;
        const position = new THREE.Vector3((column - 2 + shift) * 0.95, (row - 1.5 + shift) * 0.95, -layer * 1.2);
        const r = 0.26 + 0.16 * (((i * 7) % 11) / 10);
        const scale = new THREE.Vector3(r, r * (0.8 + 0.2 * ((i * 3) % 5) * 0.25), r);
        const turn = new THREE.Quaternion().setFromAxisAngle(position.clone().normalize(), 0.3 * i);
        spheres.setMatrixAt(i, matrix.compose(position, turn, scale));
        spheres.setColorAt(i, color.setHSL((i * 0.137) % 1, 0.65, 0.55));
        i++;
      }
    }
  }
${outlineEach(imports, '[spheres]', outline)}  return spheres;
}`,
    build: (material) => `instancedSpheres(${material})`,
  };
}

/** The scene lit by three's lights, with fog and a clipping plane (`engine/scenes/lights.ts`). */
function threeLights(imports: Imports, flat: boolean, outline: Options | null): SceneCode {
  imports.add('@shadelab/sphere', 'SubdivisionSphereGeometry');
  imports.add('@shadelab/material', 'type ShadingMaterial');
  const g = (geometry: string) => prepared(imports, flat, geometry);
  return {
    declaration: `/**
 * Meshes lit by three's hemisphere, ambient, directional, point and spot lights (besides the PhongLights), one
 * sphere opened by a clipping plane; \`material()\` makes each part's material.
 */
function threeLightsScene(material: () => ShadingMaterial): THREE.Group {
  const tilted = new THREE.Group();
  tilted.rotation.x = 0.38; // seen from slightly above
  const solid = material();
  const ground = material();
  const clipped = material();
  clipped.clippingPlanes = [new THREE.Plane(new THREE.Vector3(0.15, -0.25, -1).normalize(), 0.39)];
  clipped.side = THREE.DoubleSide;
  const add = (geometry: THREE.BufferGeometry, m: ShadingMaterial, x: number, y: number, z: number) => {
    const mesh = new THREE.Mesh(geometry, m);
    mesh.position.set(x, y, z);
    tilted.add(mesh);
    return mesh;
  };
  add(${g('new THREE.PlaneGeometry(7, 14, 14, 28)')}, ground, 0, -1, -4).rotation.x = -Math.PI / 2;
  add(${g("new SubdivisionSphereGeometry({ base: 'icosahedron', level: 4, radius: 0.8, normals: 'none' })")}, clipped, -1.05, -0.2, 0);
  add(${g('new THREE.BoxGeometry(0.9, 0.9, 0.9, 4, 4, 4)')}, solid, 1.15, -0.45, 0.2).rotation.set(0.3, 0.6, 0);
  add(${g('new THREE.TorusGeometry(0.55, 0.2, 24, 64)')}, solid, 0.2, -0.1, -2.2).rotation.x = -0.5;
  for (let i = 0; i < 3; i++) {
    const sphere = ${g("new SubdivisionSphereGeometry({ base: 'icosahedron', level: 3, radius: 0.45, normals: 'none' })")};
    add(sphere, solid, -1.6 + 1.6 * i, -0.55, -4.5 - 1.8 * i);
  }
${outlineEach(imports, '[...tilted.children] as THREE.Mesh[]', outline)}  // three's lights carry three's 1/π: these intensities give the look shown.
  const sun = new THREE.DirectionalLight(0xfff2dd, 0.25 * Math.PI);
  sun.position.set(3, 5, 4);
  const point = new THREE.PointLight(0xff44aa, 1.2 * Math.PI, 0, 2);
  point.position.set(-0.2, 0.6, 1.2);
  const spot = new THREE.SpotLight(0x33ccff, 10 * Math.PI, 0, 0.35, 0.4, 2);
  spot.position.set(1.6, 2.6, 1.6);
  spot.target.position.set(1.15, -0.45, 0.2);
  const hemisphere = new THREE.HemisphereLight(0x8899ff, 0x332211, 0.15 * Math.PI);
  const ambient = new THREE.AmbientLight(0xffffff, 0.05 * Math.PI);
  tilted.add(hemisphere, ambient, sun, sun.target, point, spot, spot.target);
  return new THREE.Group().add(tilted);
}`,
    build: (material) => `threeLightsScene(() => ${material})`,
    fog: { color: '0x1a2233', near: 3.5, far: 9.5 },
    clipping: true,
  };
}

/**
 * A glTF model (the URL is a placeholder): its materials swapped for ShadingMaterials that keep its colours and
 * maps, framed by its bounding sphere (radius 1.5, as the playground frames it), outlined, lit by the
 * playground's rig of three's lights besides the PhongLights.
 */
function model(imports: Imports, swap: Options, outline: Options | null): SceneCode {
  imports.add('@shadelab/material', 'swapMaterials');
  const options = Object.keys(swap).length ? `, ${objectLiteral(swap)}` : '';
  return {
    declaration: `/** The model framed (its bounding sphere at the origin, radius 1.5), its materials swapped. */
function shadedModel(model: THREE.Object3D): THREE.Group {
  swapMaterials(model${options});
  const bounds = new THREE.Box3().setFromObject(model).getBoundingSphere(new THREE.Sphere());
  const scale = 1.5 / bounds.radius;
  const framed = new THREE.Group().add(model);
  framed.scale.setScalar(scale);
  framed.position.copy(bounds.center).multiplyScalar(-scale);
  const meshes: THREE.Mesh[] = [];
  model.traverse((object) => {
    if (object instanceof THREE.Mesh) meshes.push(object);
  });
${outlineEach(imports, 'meshes', outline)}  return new THREE.Group().add(framed);
}

/** three's lights for the model (world space: they stay while the trackball turns it): sky, key and fill. */
function modelLightRig(): THREE.Group {
  const key = new THREE.DirectionalLight(0xffffff, 1.8);
  key.position.set(2, 3, 4);
  const fill = new THREE.DirectionalLight(0xffffff, 0.5);
  fill.position.set(-4, 0, 3);
  return new THREE.Group().add(new THREE.HemisphereLight(0xffffff, 0x333333, 0.8), key, key.target, fill, fill.target);
}`,
    build: () => 'shadedModel(gltf.scene)',
    world: 'modelLightRig()',
  };
}

/** The placeholder URL of a model: the program says to put the user's file there. */
export const MODEL_URL = '/model.glb';

/** The code of the demo scene `name` ('model': a glTF loaded from {@link MODEL_URL}). */
export function sceneCode(
  imports: Imports,
  name: 'instanced' | 'skinned' | 'textured' | 'lights' | 'model',
  { flat, outline, swap }: { flat: boolean; outline: Options | null; swap: Options },
): SceneCode {
  switch (name) {
    case 'instanced':
      return instanced(imports, flat, outline);
    case 'lights':
      return threeLights(imports, flat, outline);
    case 'model':
      return model(imports, swap, outline);
    case 'skinned':
      return skinned(imports, flat, outline);
    case 'textured':
      return textured(imports, flat, outline);
  }
}
