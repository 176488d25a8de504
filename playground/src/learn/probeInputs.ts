/**
 * What the probe hands `explainShade`, read from the objects as the GPU reads them: the model and normal matrices
 * (an instance's included, `normalMatrix: 'model'` honoured), the PhongLights and three's lights as `shade` takes
 * them, the material's options, and what the material's `output` option draws of the explanation.
 */
import {
  computeNormalMatrix,
  type PhongLight,
  type ShadeLight,
  type ShadeMaterial,
  type ShadeThreeLight,
  type ShadingMaterial,
} from '@shadelab/material';
import type { ShadeExplanation } from '@shadelab/material/explain';
import * as THREE from 'three';
import type { V3 } from './probeMath';
import type { V4 } from './probeTexture';

const v3 = (v: THREE.Vector3): V3 => [v.x, v.y, v.z];

/** The mesh's world matrix, times the instance's matrix for an InstancedMesh. */
export function modelOf(mesh: THREE.Mesh, instanceId: number | null): THREE.Matrix4 {
  const model = mesh.matrixWorld.clone();
  if (instanceId !== null && (mesh as THREE.InstancedMesh).isInstancedMesh) {
    const instance = new THREE.Matrix4();
    (mesh as THREE.InstancedMesh).getMatrixAt(instanceId, instance);
    model.multiply(instance);
  }
  return model;
}

/**
 * The normal matrix the material uses: sign(det)·cof of the world matrix (or, with `normalMatrix: 'model'`, the
 * world matrix itself: the lecture's wrong way), times the instance's sign(det)·cof for an InstancedMesh.
 */
export function normalMatrixOf(
  mesh: THREE.Mesh,
  instanceId: number | null,
  material: ShadingMaterial,
): THREE.Matrix3 {
  const modelNormals = (material as { normalMatrix?: string }).normalMatrix === 'model';
  const matrix = modelNormals
    ? new THREE.Matrix3().setFromMatrix4(mesh.matrixWorld)
    : computeNormalMatrix(mesh.matrixWorld, new THREE.Matrix3());
  if (instanceId !== null && (mesh as THREE.InstancedMesh).isInstancedMesh) {
    const instance = new THREE.Matrix4();
    (mesh as THREE.InstancedMesh).getMatrixAt(instanceId, instance);
    matrix.multiply(computeNormalMatrix(instance, new THREE.Matrix3()));
  }
  return matrix;
}

/**
 * The PhongLights that light the material, as ShadingMaterial takes them: its `phongLights` list when it is not
 * empty, else the scene's visible PhongLights in traversal order.
 */
export function phongLightsOf(material: ShadingMaterial, scene: THREE.Scene): readonly PhongLight[] {
  if (material.phongLights.length > 0) return material.phongLights;
  const found: PhongLight[] = [];
  scene.traverseVisible((object) => {
    if ((object as { isPhongLight?: boolean }).isPhongLight) found.push(object as PhongLight);
  });
  return found;
}

/** The PhongLights that light the material and three's lights in the scene, as `shade` takes them. */
export function lightsOf(material: ShadingMaterial, scene: THREE.Scene): (ShadeLight | ShadeThreeLight)[] {
  const at = new THREE.Vector3();
  const lights: (ShadeLight | ShadeThreeLight)[] = phongLightsOf(material, scene).map((l) => ({
    position: v3(l.getWorldPosition(at)),
    ambient: l.ambient.toArray(),
    diffuse: l.diffuse.toArray(),
    specular: l.specular.toArray(),
    attenuation: l.attenuation,
  }));
  scene.traverseVisible((object) => {
    const light = object as THREE.Light;
    if (!light.isLight || (object as { isPhongLight?: boolean }).isPhongLight) return;
    const world = light.getWorldPosition(new THREE.Vector3());
    const color = light.color.clone().multiplyScalar(light.intensity).toArray();
    if ((light as THREE.AmbientLight).isAmbientLight) lights.push({ type: 'ambient', color });
    else if ((light as THREE.HemisphereLight).isHemisphereLight) {
      const ground = (light as THREE.HemisphereLight).groundColor.clone().multiplyScalar(light.intensity);
      lights.push({
        type: 'hemisphere',
        color,
        groundColor: ground.toArray(),
        direction: v3(world.normalize()),
      });
    } else {
      const target = (light as THREE.DirectionalLight).target?.getWorldPosition(new THREE.Vector3());
      const direction = target ? v3(world.clone().sub(target).normalize()) : undefined;
      if ((light as THREE.DirectionalLight).isDirectionalLight)
        lights.push({ type: 'directional', color, direction });
      else {
        const point = light as THREE.PointLight;
        const base = { color, position: v3(world), distance: point.distance, decay: point.decay };
        const spot = light as THREE.SpotLight;
        if (spot.isSpotLight) {
          const [coneCos, penumbraCos] = [Math.cos(spot.angle), Math.cos(spot.angle * (1 - spot.penumbra))];
          lights.push({ type: 'spot', ...base, direction, coneCos, penumbraCos });
        } else if (point.isPointLight) lights.push({ type: 'point', ...base });
      }
    }
  });
  return lights;
}

/** The material as `shade` takes it. */
export function shadeMaterialOf(m: ShadingMaterial): ShadeMaterial {
  return {
    ka: m.ka.toArray(),
    kd: m.kd.toArray(),
    ks: m.ks.toArray(),
    shininess: m.shininess,
    lighting: m.lighting,
    celBands: m.celBands,
    emissive: m.emissive.toArray(),
  };
}

/**
 * What the material draws at a point for its `output` option: the colour (the sum); the ambient, diffuse or
 * specular terms summed over the lights; the attenuation averaged over the direct lights; or the unit normal in
 * view space packed as n·0.5 + 0.5 (three's MeshNormalMaterial).
 */
export function outputOf(e: ShadeExplanation, output: string, view: THREE.Matrix4): V3 {
  const total = (term: 'ambient' | 'diffuse' | 'specular'): V3 => {
    const out: V3 = [0, 0, 0];
    for (const light of e.lights) for (let k = 0; k < 3; k++) out[k] += light[term][k]!;
    return out;
  };
  switch (output) {
    case 'ambient':
    case 'diffuse':
    case 'specular':
      return total(output);
    case 'attenuation': {
      const direct = e.lights.filter((light) => light.l !== null);
      const mean = direct.reduce((sum, light) => sum + light.attenuation, 0) / Math.max(direct.length, 1);
      return [mean, mean, mean];
    }
    case 'normal': {
      const n = new THREE.Vector3(...e.n).transformDirection(view);
      return [n.x * 0.5 + 0.5, n.y * 0.5 + 0.5, n.z * 0.5 + 0.5];
    }
    default:
      return e.sum;
  }
}

/**
 * Vertex `index`'s object normal as three's vertex stage makes it: the normal attribute (or, without one, the
 * position: a sphere's analytic normal) with the morph targets' normals blended in (`morphnormal_vertex`), then
 * skinned by the bones' matrices as a direction (`skinnormal_vertex`).
 */
export function objectNormalOf(mesh: THREE.Mesh, index: number, position: THREE.Vector3): THREE.Vector3 {
  const geometry = mesh.geometry;
  const normals = geometry.getAttribute('normal');
  if (!normals) return position.clone();
  const normal = new THREE.Vector3().fromBufferAttribute(normals, index);
  const morphs = geometry.morphAttributes.normal;
  const influences = mesh.morphTargetInfluences;
  if (morphs && influences) {
    const target = new THREE.Vector3();
    let sum = 0;
    const blended = new THREE.Vector3();
    for (let k = 0; k < morphs.length; k++) {
      const influence = influences[k] ?? 0;
      if (influence === 0) continue;
      sum += influence;
      blended.addScaledVector(target.fromBufferAttribute(morphs[k]!, index), influence);
    }
    if (!geometry.morphTargetsRelative) normal.multiplyScalar(1 - sum);
    normal.add(blended);
  }
  const skinned = mesh as THREE.SkinnedMesh;
  if (skinned.isSkinnedMesh) {
    const skinIndex = geometry.getAttribute('skinIndex');
    const skinWeight = geometry.getAttribute('skinWeight');
    const { bones, boneInverses } = skinned.skeleton;
    const skin = new THREE.Matrix4().multiplyScalar(0);
    const bone = new THREE.Matrix4();
    for (let k = 0; k < 4; k++) {
      const weight = skinWeight.getComponent(index, k);
      if (weight === 0) continue;
      const b = skinIndex.getComponent(index, k);
      bone.multiplyMatrices(bones[b]!.matrixWorld, boneInverses[b]!);
      for (let e = 0; e < 16; e++) skin.elements[e]! += weight * bone.elements[e]!;
    }
    skin.premultiply(skinned.bindMatrixInverse).multiply(skinned.bindMatrix);
    normal.transformDirection(skin); // a direction: its length is normalised after the normal matrix anyway
  }
  return normal;
}

/**
 * The normal a normal map gives (three's `normal_fragment_maps`): in tangent space through three's derivative
 * tangent frame (`getTangentFrame`, from the point's and the uv's change across one pixel, `q0`/`st0` to the
 * right and `q1`/`st1` upwards), or in object space through the normal matrix; turned to the drawn side.
 */
export function perturbedNormal(
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
