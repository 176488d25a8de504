/**
 * The lecture's equation at a probed hit, as the material's shading evaluates it on the GPU: per fragment at the
 * hit point with the interpolated normal (Phong shading; a normal map through three's tangent frame), per vertex
 * and blended by the barycentric weights (Gouraud), once per face at its centroid or per fragment with the face
 * normal (flat); with the lights the material draws with, its tints and its textures' texels at the pixel.
 */
import { eyeOf, fogFactor, type ShadingMaterial } from '@shadelab/material';
import { explainShade, type ShadeExplanation } from '@shadelab/material/explain';
import * as THREE from 'three';
import {
  lightsOf,
  modelOf,
  normalMatrixOf,
  objectNormalOf,
  outputOf,
  perturbedNormal,
  shadeMaterialOf,
} from './probeInputs';
import { barycentric, blend, displayed8, nearCelEdge, raw8, type V3 } from './probeMath';
import { probedSurface } from './probeSurface';

/** One vertex of a Gouraud-shaded triangle: where it is lit and its colour (or output term; linear, unclamped). */
export interface ProbeVertex {
  readonly point: V3;
  readonly normal: V3;
  readonly color: V3;
  readonly explanation: ShadeExplanation;
}

/** A probe that met a surface. */
export interface ProbeHit {
  readonly hit: true;
  readonly pixel: [number, number];
  readonly mesh: THREE.Mesh;
  readonly material: ShadingMaterial;
  readonly instanceId: number | null;
  /** The ray's point on the surface (world). */
  readonly point: V3;
  /** The same point in the mesh's (or the instance's) own space: what the probe follows when the view moves. */
  readonly local: V3;
  /** Where the equation was evaluated (the hit point, a Gouraud vertex, a flat face's centroid) and its label. */
  readonly at: V3;
  readonly atLabel: string;
  /** The lecture's terms there (its `n` is the normal lit with). */
  readonly explanation: ShadeExplanation;
  /** Gouraud: the triangle's vertices and the weights that blend their colours at the pixel. */
  readonly gouraud: { readonly vertices: readonly ProbeVertex[]; readonly weights: V3 } | null;
  /** Flat: the face's centroid and normal (per fragment when the geometry has no prepared corners). */
  readonly flat: { readonly centroid: V3; readonly normal: V3; readonly perFragment: boolean } | null;
  /** What the material draws (its `output` option): 'color', or a term view. */
  readonly output: string;
  /** The pixel's linear colour (unclamped): the sum (or the output's term) at `at`, or the Gouraud blend. */
  readonly linear: V3;
  /** The 8-bit sRGB colour the canvas should hold (after fog). */
  readonly srgb8: V3;
  /** three's fog factor at the point; null without fog. */
  readonly fog: number | null;
  /** Ties the GPU may break either way here (a centre on a flat face's edge, a light at a cel band's edge). */
  readonly notes: readonly string[];
  /** What the probe could not compute here (a minified texture's texel, …): when any, it shows no colour. */
  readonly unreproduced: readonly string[];
}

/** The note on such a pixel. */
const ON_EDGE =
  'The pixel’s centre is on an edge (within 1/64 pixel): the GPU’s rasteriser may draw the neighbouring face.';
/** The note on a pixel lit at a cel band's edge, where float rounding decides the band. */
const ON_CEL_EDGE =
  'The light is at a cel band’s edge here: the GPU’s float rounding may put the pixel in the next band.';
const v3 = (v: THREE.Vector3): V3 => [v.x, v.y, v.z];

export function explainHit(
  scene: THREE.Scene,
  camera: THREE.Camera,
  mesh: THREE.Mesh,
  material: ShadingMaterial,
  found: THREE.Intersection,
  ray: THREE.Vector3,
  pixel: [number, number],
  size: [number, number],
): ProbeHit {
  const notes: string[] = [];
  const instanceId = found.instanceId ?? null;
  const model = modelOf(mesh, instanceId);
  const inverse = model.clone().invert();
  const geometry = mesh.geometry;
  const { a, b, c } = found.face!;
  const corners = [a, b, c].map((i) => mesh.getVertexPosition(i, new THREE.Vector3()));
  const [pa, pb, pc] = corners as [THREE.Vector3, THREE.Vector3, THREE.Vector3];
  const local = found.point.clone().applyMatrix4(inverse);
  const weights = barycentric(v3(local), v3(pa), v3(pb), v3(pc));
  const normalMatrix = normalMatrixOf(mesh, instanceId, material);
  // The face as drawn: its object-space winding normal against the ray (three's front face), then the side.
  const faceNormal = pb.clone().sub(pa).cross(pc.clone().sub(pa));
  const rayLocal = ray.clone().applyMatrix3(new THREE.Matrix3().setFromMatrix4(inverse));
  const front = faceNormal.dot(rayLocal) < 0;
  const side = material.side;
  const sign = side === THREE.BackSide || (side === THREE.DoubleSide && !front) ? -1 : 1;
  // The tint: instance colour × vertex colour (three's USE_COLOR when vertexColors is on).
  const instanceColor = new THREE.Color(1, 1, 1);
  if (instanceId !== null && (mesh as THREE.InstancedMesh).instanceColor)
    (mesh as THREE.InstancedMesh).getColorAt(instanceId, instanceColor);
  const colors = material.vertexColors ? geometry.getAttribute('color') : undefined;
  const tints = [a, b, c].map((i): V3 => {
    const t = v3(new THREE.Vector3(instanceColor.r, instanceColor.g, instanceColor.b));
    if (colors) for (let k = 0; k < 3; k++) t[k]! *= colors.getComponent(i, k);
    return t;
  });
  const output = (material as { output?: string }).output ?? 'color';
  const drawnValue = (e: ShadeExplanation) => outputOf(e, output, camera.matrixWorldInverse);

  // The textures at the pixel, read as the GPU samples them.
  const surface = probedSurface({
    camera,
    geometry,
    indices: [a, b, c],
    corners: [pa, pb, pc],
    model,
    weights,
    pixel,
    size,
  });
  const unreproduced: string[] = [];
  const sample = (texture: THREE.Texture | null, what: string) => surface.sample(texture, what, unreproduced);
  const texel = sample(material.map, 'texture');
  const emissiveTexel = sample(material.emissiveMap, 'emissive map');
  const texelTint = (t: V3): V3 => (texel ? [t[0] * texel[0], t[1] * texel[1], t[2] * texel[2]] : t);

  const eye = eyeOf(camera, new THREE.Vector4()).toArray();
  const emissive = material.emissive.toArray();
  const shadeMaterial = {
    ...shadeMaterialOf(material),
    emissive: emissiveTexel ? emissive.map((e, k) => e * emissiveTexel[k]!) : emissive,
  };
  const lights = lightsOf(material, scene);
  const explain = (position: V3, normal: V3, tint: V3) =>
    explainShade({ position, normal, eye, tint }, shadeMaterial, lights);
  const toWorld = (p: THREE.Vector3) => v3(p.clone().applyMatrix4(model));
  const worldNormal = (n: THREE.Vector3) => v3(n.clone().applyMatrix3(normalMatrix).multiplyScalar(sign));
  const point = v3(found.point);
  // Lit in the vertex stage with a texture: the ka/kd part × the texel at the fragment, plus the ks part.
  const split = texel !== null && output === 'color';
  const splitColor = (ad: V3, specular: V3, emitted: V3): V3 =>
    [0, 1, 2].map((k) => ad[k]! * texel![k]! + specular[k]! + emitted[k]!) as V3;
  const parts = (e: ShadeExplanation) => {
    const ad: V3 = [0, 0, 0];
    const specular: V3 = [0, 0, 0];
    for (const light of e.lights)
      for (let k = 0; k < 3; k++) {
        ad[k]! += light.ambient[k]! + light.diffuse[k]!;
        specular[k]! += light.specular[k]!;
      }
    return { ad, specular };
  };
  if (material.map && output !== 'color' && material.shading !== 'phong')
    unreproduced.push('A term view of a textured, vertex-lit surface is not reproduced.');

  let at = point;
  let atLabel = 'the hit point';
  let explanation: ShadeExplanation;
  let linear: V3;
  let gouraud: ProbeHit['gouraud'] = null;
  let flat: ProbeHit['flat'] = null;
  if (material.shading === 'flat') {
    const perFragment = geometry.index !== null && !geometry.getAttribute('flatCornerA');
    const normal = worldNormal(faceNormal);
    if (!perFragment) {
      at = toWorld(pa.clone().add(pb).add(pc).divideScalar(3));
      atLabel = 'the face’s centroid';
    }
    // The provoking vertex's tint (the last on WebGL2); lit per fragment, the texel is in the tint.
    explanation = explain(at, normal, perFragment ? texelTint(tints[2]!) : tints[2]!);
    // Within a rasteriser's sub-pixel precision of an edge, the GPU may draw the neighbouring face here.
    if (surface.nearEdge()) notes.push(ON_EDGE);
    flat = {
      centroid: toWorld(pa.clone().add(pb).add(pc).divideScalar(3)),
      normal: explanation.n,
      perFragment,
    };
    if (split && !perFragment) {
      const { ad, specular } = parts(explanation);
      linear = splitColor(ad, specular, explanation.emissive as V3);
    } else linear = drawnValue(explanation);
  } else if (material.shading === 'gouraud') {
    const vertices = [a, b, c].map((index, i): ProbeVertex => {
      const p = corners[i]!;
      const e = explain(toWorld(p), worldNormal(objectNormalOf(mesh, index, p)), tints[i]!);
      return { point: toWorld(p), normal: e.n, color: drawnValue(e), explanation: e };
    });
    const k = weights.indexOf(Math.max(...weights));
    at = vertices[k]!.point;
    atLabel = `vertex ${k + 1} (the largest weight)`;
    explanation = vertices[k]!.explanation;
    gouraud = { vertices, weights };
    if (split) {
      const blended = vertices.map((vertex) => parts(vertex.explanation));
      linear = splitColor(
        blend(blended.map((p) => p.ad) as [V3, V3, V3], weights),
        blend(blended.map((p) => p.specular) as [V3, V3, V3], weights),
        explanation.emissive as V3,
      );
    } else linear = blend([vertices[0]!.color, vertices[1]!.color, vertices[2]!.color], weights);
  } else {
    // Phong shading: the unit vertex normals (world) blended, the tint blended, lit at the hit point.
    const unit = [a, b, c].map((index, i): V3 => {
      const n = objectNormalOf(mesh, index, corners[i]!).applyMatrix3(normalMatrix);
      const length = n.length();
      return length > 0 ? v3(n.divideScalar(length)) : [0, 0, 0];
    });
    let n = blend(unit as [V3, V3, V3], weights).map((x) => x * sign) as V3;
    if (material.normalMap) {
      const mapped = sample(material.normalMap, 'normal map');
      const frame = surface.frameOf(material.normalMap);
      if (mapped && frame) {
        n = perturbedNormal(material, mapped, n, front, normalMatrix, frame);
      }
    }
    const tint = texelTint(blend(tints as [V3, V3, V3], weights));
    explanation = explain(point, n, tint);
    linear = drawnValue(explanation);
  }
  const lit = gouraud ? gouraud.vertices.map((vertex) => vertex.explanation) : [explanation];
  if (lit.some((e) => nearCelEdge(e, material.celBands, material.shininess))) notes.push(ON_CEL_EDGE);
  let fog: number | null = null;
  const sceneFog = scene.fog;
  if (sceneFog && material.fog && output === 'color') {
    const depth = -found.point.clone().applyMatrix4(camera.matrixWorldInverse).z;
    const params = (sceneFog as THREE.FogExp2).isFogExp2
      ? { density: (sceneFog as THREE.FogExp2).density }
      : { near: (sceneFog as THREE.Fog).near, far: (sceneFog as THREE.Fog).far };
    fog = fogFactor(params, depth);
  }
  const data = output === 'attenuation' || output === 'normal'; // written as is, no colour space
  const srgb8 = data
    ? raw8(linear)
    : displayed8(linear, fog === null ? undefined : { color: sceneFog!.color.toArray(), factor: fog });
  return {
    hit: true,
    pixel,
    mesh,
    material,
    instanceId,
    point,
    local: v3(local),
    at,
    atLabel,
    explanation,
    gouraud,
    flat,
    output,
    linear,
    srgb8,
    fog,
    notes,
    unreproduced,
  };
}
