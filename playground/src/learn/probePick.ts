/**
 * Probing a pixel: the ray through its centre meets the front-most ShadingMaterial surface (the sphere, or a part
 * of the picked scene), and `explainShade` evaluates the lecture's equation there as the material's shading does
 * on the GPU: per fragment at the hit point with the interpolated normal (Phong shading), per vertex and blended by
 * the barycentric weights (Gouraud), once per face at its centroid with the face normal (flat).
 */
import { eyeOf, fogFactor, type ShadingMaterial } from '@shadelab/material';
import { explainShade, type ShadeExplanation } from '@shadelab/material/explain';
import * as THREE from 'three';
import { lightsOf, modelOf, normalMatrixOf, objectNormalOf, outputOf, shadeMaterialOf } from './probeInputs';
import { barycentric, blend, displayed8, ndcOfPixel, pixelOfNdc, raw8, type V3 } from './probeMath';
import { sampleTexture, type TexelRead, transformedUv, type V4 } from './probeTexture';

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
  /** What to know about this pixel (a centre on an edge). */
  readonly notes: readonly string[];
  /** What the probe could not compute here (a minified texture's texel, …): when any, it shows no colour. */
  readonly unreproduced: readonly string[];
}

/** A probe that met no shaded surface, and why. */
export interface ProbeMiss {
  readonly hit: false;
  readonly pixel: [number, number];
  readonly reason: string;
}

/** What a probe found. */
export type ProbeResult = ProbeHit | ProbeMiss;

const isShading = (m: unknown): m is ShadingMaterial =>
  (m as { isShadingMaterial?: boolean } | null)?.isShadingMaterial === true;
const MARKER = /^light marker/;
/** A pixel centre this near an edge (in pixels: a rasteriser's sub-pixel precision) is a tie between faces. */
const EDGE_PIXELS = 1 / 64;
/** The note on such a pixel. */
export const ON_EDGE =
  'The pixel’s centre is on an edge (within 1/64 pixel): the GPU’s rasteriser may draw the neighbouring face.';
const raycaster = new THREE.Raycaster();
const neighbour = new THREE.Raycaster();
const v3 = (v: THREE.Vector3): V3 => [v.x, v.y, v.z];

/** Whether a world point survives the material's clipping planes (three drops the negative side). */
const unclipped = (material: THREE.Material, point: THREE.Vector3) =>
  (material.clippingPlanes ?? []).every((plane) => plane.distanceToPoint(point) >= 0);

/**
 * Probes device pixel (`x`, `y`) (y from the top) of a `width` × `height` canvas showing `scene` through `camera`:
 * the front-most visible ShadingMaterial surface under the pixel's centre, explained as its shading lights it.
 */
export function probePixel(
  scene: THREE.Scene,
  camera: THREE.Camera,
  x: number,
  y: number,
  width: number,
  height: number,
): ProbeResult {
  const pixel: [number, number] = [x, y];
  const [nx, ny] = ndcOfPixel(x, y, width, height);
  raycaster.setFromCamera(new THREE.Vector2(nx, ny), camera);
  const candidates: THREE.Object3D[] = [];
  scene.traverseVisible((o) => {
    const mesh = o as THREE.Mesh;
    if (mesh.isMesh && (isShading(mesh.material) || MARKER.test(mesh.name))) candidates.push(mesh);
  });
  const found = raycaster
    .intersectObjects(candidates, false)
    .find((h) => unclipped((h.object as THREE.Mesh).material as THREE.Material, h.point));
  if (!found?.face) {
    return { hit: false, pixel, reason: 'No object under this pixel: the probe is off the object.' };
  }
  const mesh = found.object as THREE.Mesh;
  if (!isShading(mesh.material)) {
    return { hit: false, pixel, reason: `The ${mesh.name} hides the surface at this pixel.` };
  }
  return explainHit(scene, camera, mesh, mesh.material, found, pixel, [width, height]);
}

function explainHit(
  scene: THREE.Scene,
  camera: THREE.Camera,
  mesh: THREE.Mesh,
  material: ShadingMaterial,
  found: THREE.Intersection,
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
  const rayLocal = raycaster.ray.direction.clone().applyMatrix3(new THREE.Matrix3().setFromMatrix4(inverse));
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

  // The textures at the pixel. The rays through its right and upper neighbours meet the triangle's plane: the
  // surface's change across one pixel, as the GPU's derivatives see it (the level of detail, the tangent frame).
  const plane = new THREE.Plane().setFromCoplanarPoints(
    ...(corners.map((p) => p.clone().applyMatrix4(model)) as [THREE.Vector3, THREE.Vector3, THREE.Vector3]),
  );
  const onPlane = (x: number, y: number) => {
    const [nx, ny] = ndcOfPixel(x, y, size[0], size[1]);
    neighbour.setFromCamera(new THREE.Vector2(nx, ny), camera);
    const world = neighbour.ray.intersectPlane(plane, new THREE.Vector3());
    if (!world) return null;
    return { world, weights: barycentric(v3(world.clone().applyMatrix4(inverse)), v3(pa), v3(pb), v3(pc)) };
  };
  const right = onPlane(pixel[0] + 1, pixel[1]);
  const up = onPlane(pixel[0], pixel[1] - 1);
  const unreproduced: string[] = [];
  const uvsOf = (texture: THREE.Texture) => {
    const name = texture.channel === 0 ? 'uv' : `uv${texture.channel}`;
    const uv = geometry.getAttribute(name);
    if (!uv || !right || !up) return null;
    const at = (w: V3) => {
      const sum = new THREE.Vector2();
      [a, b, c].forEach((index, k) => {
        sum.addScaledVector(new THREE.Vector2(uv.getX(index), uv.getY(index)), w[k]!);
      });
      return transformedUv(texture, sum);
    };
    const here = at(weights);
    return { here, dx: at(right.weights).sub(here), dy: at(up.weights).sub(here) };
  };
  const sample = (texture: THREE.Texture | null, what: string): V4 | null => {
    if (!texture) return null;
    const uvs = uvsOf(texture);
    const read: TexelRead = uvs
      ? sampleTexture(texture, uvs.here, uvs.dx, uvs.dy)
      : { reason: 'the geometry has no uv for it' };
    if ('value' in read) return read.value;
    unreproduced.push(`The ${what}’s texel is not reproduced: ${read.reason}.`);
    return null;
  };
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
  const splitColor = (ad: V3, specular: V3, emissive: V3): V3 =>
    [0, 1, 2].map((k) => ad[k]! * texel![k]! + specular[k]! + emissive[k]!) as V3;
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
    const nearEdge = [
      [1, 0],
      [-1, 0],
      [0, 1],
      [0, -1],
    ].some(([dx, dy]) => {
      const moved = onPlane(pixel[0] + dx! * EDGE_PIXELS, pixel[1] + dy! * EDGE_PIXELS);
      return moved !== null && Math.min(...moved.weights) < 0;
    });
    if (nearEdge) notes.push(ON_EDGE);
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
      const uvs = uvsOf(material.normalMap);
      if (mapped && uvs && right && up) {
        const frame = {
          q0: right.world.clone().sub(found.point),
          q1: up.world.clone().sub(found.point),
          st0: uvs.dx,
          st1: uvs.dy,
        };
        n = perturbedNormal(material, mapped, n, front, normalMatrix, frame);
      }
    }
    const tint = texelTint(blend(tints as [V3, V3, V3], weights));
    explanation = explain(point, n, tint);
    linear = drawnValue(explanation);
  }
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

/**
 * The normal a normal map gives (three's `normal_fragment_maps`): in tangent space through three's derivative
 * tangent frame (`getTangentFrame`, from the point's and the uv's change across one pixel, `q0`/`st0` to the
 * right and `q1`/`st1` upwards), or in object space through the normal matrix; turned to the drawn side.
 */
function perturbedNormal(
  material: ShadingMaterial,
  texel: V4,
  normal: V3,
  front: boolean,
  normalMatrix: THREE.Matrix3,
  frame: { q0: THREE.Vector3; q1: THREE.Vector3; st0: THREE.Vector2; st1: THREE.Vector2 },
): V3 {
  const mapN = new THREE.Vector3(texel[0] * 2 - 1, texel[1] * 2 - 1, texel[2] * 2 - 1);
  const faceDirection = front ? 1 : -1;
  if (material.normalMapType === THREE.ObjectSpaceNormalMap) {
    if (material.side === THREE.BackSide) mapN.negate();
    if (material.side === THREE.DoubleSide) mapN.multiplyScalar(faceDirection);
    return v3(mapN.applyMatrix3(normalMatrix).normalize());
  }
  // A BackSide material's frame is turned round (three's refreshUniformsCommon negates normalScale).
  const flip = material.side === THREE.BackSide ? -1 : 1;
  mapN.x *= flip * material.normalScale.x;
  mapN.y *= flip * material.normalScale.y;
  const { q0, q1, st0, st1 } = frame;
  const n = new THREE.Vector3(...normal).normalize();
  const q1perp = q1.clone().cross(n);
  const q0perp = n.clone().cross(q0);
  const t = q1perp.clone().multiplyScalar(st0.x).addScaledVector(q0perp, st1.x);
  const b = q1perp.clone().multiplyScalar(st0.y).addScaledVector(q0perp, st1.y);
  const det = Math.max(t.dot(t), b.dot(b));
  const scale =
    (det === 0 ? 0 : 1 / Math.sqrt(det)) * (material.side === THREE.DoubleSide ? faceDirection : 1);
  t.multiplyScalar(scale);
  b.multiplyScalar(scale);
  return v3(t.multiplyScalar(mapN.x).addScaledVector(b, mapN.y).addScaledVector(n, mapN.z).normalize());
}

/**
 * Where a followed point is now: the device pixel of `local` (in `mesh`'s, or its instance's, own space) after the
 * view moved; null when it left the canvas or is behind the camera.
 */
export function pixelOfFollowed(
  camera: THREE.Camera,
  mesh: THREE.Mesh,
  instanceId: number | null,
  local: V3,
  width: number,
  height: number,
): [number, number] | null {
  const world = new THREE.Vector3(...local).applyMatrix4(modelOf(mesh, instanceId));
  const view = world.clone().applyMatrix4(camera.matrixWorldInverse);
  if ((camera as THREE.PerspectiveCamera).isPerspectiveCamera && view.z >= 0) return null;
  const ndc = world.project(camera);
  return pixelOfNdc(ndc.x, ndc.y, width, height);
}

/** The canvas's pixel (`x`, `y`), y from the top, as 8-bit RGB: what the GPU drew last (the buffer is kept). */
export function readCanvasPixel(renderer: THREE.WebGLRenderer, x: number, y: number): V3 {
  const gl = renderer.getContext();
  const out = new Uint8Array(4);
  gl.readPixels(x, gl.drawingBufferHeight - 1 - y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
  return [out[0]!, out[1]!, out[2]!];
}
