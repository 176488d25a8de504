import type { PhongLight, ShadeLight, ShadeMaterial } from '@shadelab/material';
import type { RenderReferenceOptions } from '@shadelab/reference';
import type { Camera, Color, Object3D } from 'three';

/**
 * A scene `renderReference` can draw, without the image size (the canvas gives it): one lit sphere (an
 * ellipsoid under its model matrix), the camera's matrices, the material, the lights and the background.
 */
export type ReferenceScene = Omit<RenderReferenceOptions, 'width' | 'height'>;

/** The material's options the reference reads: `ShadingMaterial`'s (or `SphereImpostorMaterial`'s). */
export interface ReferenceMaterialLike {
  /** Ambient reflectance, linear RGB. */
  readonly ka: Color;
  /** Diffuse reflectance, linear RGB. */
  readonly kd: Color;
  /** Specular reflectance, linear RGB. */
  readonly ks: Color;
  /** The specular exponent. */
  readonly shininess: number;
  /** The lighting equation. */
  readonly lighting: ShadeMaterial['lighting'];
  /** Cel bands (0: off). */
  readonly celBands: number;
  /** The lights the material is restricted to (empty: every PhongLight in the scene). */
  readonly phongLights?: readonly PhongLight[];
}

/** The three.js objects of a scene of one lit sphere, as an app builds them (see {@link referenceSceneOf}). */
export interface SceneObjects {
  /** The camera the app renders with (any three `Camera`: perspective, orthographic, the lecture `Camera`). */
  readonly camera: Camera;
  /**
   * The sphere: a mesh of a sphere centred on its origin (`SubdivisionSphereGeometry`, three's
   * `SphereGeometry`) or a `SphereImpostor`, scaled, rotated and placed by its world matrix.
   */
  readonly sphere: Object3D;
  /** Its material. @default `sphere.material` */
  readonly material?: ReferenceMaterialLike;
  /**
   * The lights. @default the material's `phongLights` when it lists some, else every `PhongLight` in the
   * sphere's scene
   */
  readonly lights?: readonly PhongLight[];
  /** The sphere's radius in model space. @default `sphere.geometry.parameters.radius`, else 1 */
  readonly radius?: number;
  /** The colour the canvas is cleared to, linear RGB (three's `renderer.setClearColor`). @default [0, 0, 0] */
  readonly background?: readonly [number, number, number];
}

const rgb = (c: Color): [number, number, number] => [c.r, c.g, c.b];

/**
 * Describe the app's own three.js objects as a {@link ReferenceScene}: the camera's projection and view
 * matrices, the sphere's world matrix and radius, the material's ka, kd, ks, shininess, lighting and cel bands,
 * and each PhongLight's world position, intensities and attenuation. World matrices are brought up to date
 * first (`updateWorldMatrix`). A test can build the scene with the app's own code and pass it here, rather than
 * repeating its parameters.
 *
 * @throws TypeError when the sphere has no material with ka, kd, ks (a `ShadingMaterial` or
 * `SphereImpostorMaterial`), or when no PhongLight lights it.
 */
export function referenceSceneOf({
  camera,
  sphere,
  material = (sphere as Object3D & { material?: ReferenceMaterialLike }).material,
  lights,
  radius,
  background = [0, 0, 0],
}: SceneObjects): ReferenceScene {
  if (material === undefined || !(material.ka?.isColor && material.kd?.isColor && material.ks?.isColor)) {
    throw new TypeError(
      'referenceSceneOf: the sphere must have a material with ka, kd and ks (a ShadingMaterial or SphereImpostorMaterial), or pass material',
    );
  }
  camera.updateWorldMatrix(true, false);
  sphere.updateWorldMatrix(true, false);
  let root: Object3D = sphere;
  while (root.parent !== null) root = root.parent;
  const found: PhongLight[] = [];
  if (lights === undefined && !(material.phongLights !== undefined && material.phongLights.length > 0)) {
    root.traverse((o) => {
      if ((o as Partial<PhongLight>).isPhongLight === true) found.push(o as PhongLight);
    });
  }
  const chosen = lights ?? (material.phongLights?.length ? material.phongLights : found);
  if (chosen.length === 0) {
    throw new TypeError(
      "referenceSceneOf: no PhongLight lights the sphere (none in the material's phongLights or in its scene): pass lights",
    );
  }
  const shadeLights: ShadeLight[] = chosen.map((light) => {
    light.updateWorldMatrix(true, false);
    const e = light.matrixWorld.elements;
    return {
      position: [e[12], e[13], e[14]],
      ambient: rgb(light.ambient),
      diffuse: rgb(light.diffuse),
      specular: rgb(light.specular),
      attenuation: { ...light.attenuation },
    };
  });
  const geometry = (sphere as Object3D & { geometry?: { parameters?: { radius?: unknown } } }).geometry;
  const r = radius ?? geometry?.parameters?.radius;
  return {
    projectionMatrix: Array.from(camera.projectionMatrix.elements),
    viewMatrix: Array.from(camera.matrixWorldInverse.elements),
    modelMatrix: Array.from(sphere.matrixWorld.elements),
    radius: typeof r === 'number' ? r : 1,
    material: {
      ka: rgb(material.ka),
      kd: rgb(material.kd),
      ks: rgb(material.ks),
      shininess: material.shininess,
      lighting: material.lighting,
      celBands: material.celBands,
    },
    lights: shadeLights,
    background: [...background],
  };
}
