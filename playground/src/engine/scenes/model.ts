/**
 * The user's own model as a picked scene: a glTF that `../modelLoader.ts` parsed, framed (its bounding sphere
 * centred on the trackball's centre and scaled to {@link MODEL_RADIUS}), its materials swapped for
 * ShadingMaterials by `swapMaterials` (they keep the model's colours, maps and sides; the panel sets the
 * shading, lighting, cel bands and outline live through `update`), lit by a light rig of three's lights as a
 * glTF viewer lights MeshStandard/MeshPhong models, and its first animation clip playing.
 *
 * Flat shading draws each mesh's own geometry: the material's derivative path for a plain indexed geometry
 * (each fragment lit with its face's normal, what three's `flatShading` does), which needs no copy and keeps
 * every attribute of the file (uv, colours, groups, skin and morph targets).
 */
import { ShadingMaterial, type SwappedMaterials, swapMaterials } from '@shadelab/material';
import * as THREE from 'three';
import { createOutlineMesh } from '../meshes';
import type { LoadedModel } from '../modelLoader';
import type { DemoScene, ScenePart } from './types';

/** The radius the model's bounding sphere is scaled to (world units; the default view shows 1.83 whole). */
export const MODEL_RADIUS = 1.5;

/**
 * The light rig (world space: it stays while the trackball turns the model): a hemisphere light (sky above, dark
 * ground below), a key directional light from the upper right front and a weaker fill from the left front, at
 * intensities a MeshStandard/MeshPhong scene without tone mapping takes (the brightest diffuse point gets about
 * 0.83 × its colour: (0.8 + 1.8) / π). ShadingMaterial receives three's lights with three's 1/π, as three's
 * materials do, so the model looks as it would with its own materials, then shaded as the panel says.
 */
export const MODEL_RIG = {
  hemisphere: { sky: 0xffffff, ground: 0x333333, intensity: 0.8 },
  key: { color: 0xffffff, intensity: 1.8, position: [2, 3, 4] as const },
  fill: { color: 0xffffff, intensity: 0.5, position: [-4, 0, 3] as const },
} as const;

/** The model's scene for the picker, with what the page says about it. */
export interface ModelScene extends DemoScene {
  /** The file's name. */
  readonly name: string;
  /** Meshes in the model, and how many are drawn with a ShadingMaterial (all or some of their materials). */
  readonly meshes: number;
  readonly shaded: number;
  /** What the swap left in place, with the reason (one line per distinct reason). */
  readonly skipped: readonly string[];
  /** The animation clip playing, if the model has one. */
  readonly clip: { name: string; seconds: number } | null;
  /** Plays or pauses the animation. */
  playing: boolean;
}

/** Builds the model's scene from a parsed glTF (which it then owns: `dispose` frees it). */
export function createModelScene(model: LoadedModel): ModelScene {
  const content = model.scene;
  const frame = new THREE.Group();
  frame.name = 'model frame';
  frame.add(content);
  try {
    frameModel(frame, content, model.name);
  } catch (error) {
    disposeObject(content);
    throw error;
  }
  const root = new THREE.Group();
  root.name = `model: ${model.name}`;
  root.add(frame);
  root.updateMatrixWorld(true);

  const swapped: SwappedMaterials = swapMaterials(content);
  const parts: (ScenePart & { scale: number })[] = [];
  // The meshes first: each part adds its outline (a mesh) under its mesh.
  const found: THREE.Mesh[] = [];
  content.traverse((object) => {
    if ((object as THREE.Mesh).isMesh) found.push(object as THREE.Mesh);
  });
  const meshes = found.length;
  for (const mesh of found) {
    const materials = Array.isArray(mesh.material) ? mesh.material : [mesh.material];
    const material = materials.find((m): m is ShadingMaterial => m instanceof ShadingMaterial);
    // Animated skins move outside their rest bounds.
    if ((mesh as THREE.SkinnedMesh).isSkinnedMesh) mesh.frustumCulled = false;
    if (!material || (mesh as THREE.BatchedMesh).isBatchedMesh) continue;
    parts.push(modelPart(mesh, material));
  }
  const reasons = [...new Set(swapped.skipped.map((s) => s.reason))];

  const mixer = model.animations.length > 0 ? new THREE.AnimationMixer(content) : null;
  const clip = model.animations[0];
  if (mixer && clip) mixer.clipAction(clip).play();

  const rig = createRig();
  let options: { width: number } = { width: 0 };
  const scene: ModelScene = {
    name: model.name,
    root,
    parts,
    meshes,
    shaded: parts.length,
    skipped: reasons,
    clip: clip ? { name: clip.name || 'clip 1', seconds: clip.duration } : null,
    playing: mixer !== null,
    get animating() {
      return mixer !== null && scene.playing;
    },
    enter(three) {
      three.add(rig);
    },
    leave(three) {
      three.remove(rig);
    },
    applyMaterial(panel) {
      swapped.update({ shading: panel.shading, lighting: panel.lighting, celBands: panel.celBands });
      options = { width: panel.outlineWidth };
      for (const part of parts) {
        // The panel's width is in the framed model's units: each mesh's outline in its own.
        part.outline.material.thickness = options.width / part.scale;
        part.outline.material.color = panel.outlineColor;
      }
    },
    setShading(shading, celBands) {
      for (const material of swapped.materials) {
        material.shading = shading;
        material.celBands = celBands;
      }
    },
    step(seconds) {
      if (mixer && scene.playing) mixer.update(seconds);
    },
    dispose() {
      mixer?.stopAllAction();
      mixer?.uncacheRoot(content);
      for (const part of parts) part.dispose();
      swapped.restore();
      disposeObject(content);
      for (const light of rig.children) (light as THREE.Light).dispose?.();
    },
  };
  return scene;
}

/**
 * Centres the model's bounding sphere on the origin and scales it to {@link MODEL_RADIUS}: the centre of its
 * bounding box, the radius of the farthest vertex from it (tighter than the box's own sphere). Vertices as three
 * draws them: skin and morph targets applied, not the rest bounds.
 */
function frameModel(frame: THREE.Group, content: THREE.Object3D, name: string): void {
  frame.updateMatrixWorld(true);
  const box = new THREE.Box3().setFromObject(content, true);
  const center = box.getCenter(new THREE.Vector3());
  const vertex = new THREE.Vector3();
  let radius = 0;
  content.traverse((object) => {
    const { geometry } = object as THREE.Mesh;
    const position = geometry?.getAttribute?.('position');
    if (!position) return;
    for (let i = 0; i < position.count; i++) {
      if ((object as THREE.Mesh).isMesh) (object as THREE.Mesh).getVertexPosition(i, vertex);
      else vertex.fromBufferAttribute(position, i);
      radius = Math.max(radius, vertex.applyMatrix4(object.matrixWorld).distanceTo(center));
    }
  });
  if (box.isEmpty() || !(radius > 0) || !Number.isFinite(radius)) {
    throw new RangeError(`"${name}" has no extent to frame (its bounding sphere's radius is ${radius}).`);
  }
  const scale = MODEL_RADIUS / radius;
  frame.scale.setScalar(scale);
  frame.position.copy(center).multiplyScalar(-scale);
}

/** A mesh of the model with its outline; `scale`: the mesh's world scale in the framed model (largest axis). */
function modelPart(mesh: THREE.Mesh, material: ShadingMaterial): ScenePart & { scale: number } {
  const outline = createOutlineMesh(mesh);
  outline.visible = false;
  const s = new THREE.Vector3().setFromMatrixScale(mesh.matrixWorld);
  const scale = Math.max(Math.abs(s.x), Math.abs(s.y), Math.abs(s.z)) || 1;
  return {
    mesh,
    material,
    outline,
    scale,
    geometry: () => mesh.geometry,
    dispose() {
      mesh.remove(outline);
      outline.material.dispose();
    },
  };
}

function createRig(): THREE.Group {
  const { hemisphere, key, fill } = MODEL_RIG;
  const rig = new THREE.Group();
  rig.name = 'model light rig';
  rig.add(new THREE.HemisphereLight(hemisphere.sky, hemisphere.ground, hemisphere.intensity));
  for (const { color, intensity, position } of [key, fill]) {
    const light = new THREE.DirectionalLight(color, intensity);
    light.position.fromArray(position);
    rig.add(light, light.target);
  }
  return rig;
}

/** Frees what three's GLTFLoader made for the model: geometries, its own materials and their textures, skeletons. */
function disposeObject(content: THREE.Object3D): void {
  const materials = new Set<THREE.Material>();
  content.traverse((object) => {
    const mesh = object as THREE.Mesh & Partial<THREE.SkinnedMesh & THREE.InstancedMesh>;
    mesh.geometry?.dispose();
    if (mesh.material) for (const m of [mesh.material].flat()) materials.add(m);
    mesh.skeleton?.dispose();
    if (mesh.isInstancedMesh) mesh.dispose?.();
  });
  for (const material of materials) {
    for (const value of Object.values(material))
      if ((value as THREE.Texture)?.isTexture) (value as THREE.Texture).dispose();
    material.dispose();
  }
}
