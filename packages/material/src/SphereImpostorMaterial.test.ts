import { PhongLight, ShadingMaterial } from '@shadelab/material';
import {
  createImpostorQuad,
  projectedBounds,
  SphereImpostor,
  SphereImpostorMaterial,
} from '@shadelab/material/impostor';
import fc from 'fast-check';
import {
  Euler,
  Matrix4,
  OrthographicCamera,
  PerspectiveCamera,
  Quaternion,
  Scene,
  Vector3,
  Vector4,
  type WebGLRenderer,
} from 'three';
import { describe, expect, it } from 'vitest';
import { lightingChunk } from './lightingChunks.glsl.js';
import { fragmentShader, vertexShader } from './ShadingMaterial.glsl.js';

const renderer = { getCurrentViewport: (v: Vector4) => v.set(0, 0, 1280, 720) } as unknown as WebGLRenderer;

function lectureCamera(): PerspectiveCamera {
  const camera = new PerspectiveCamera(90, 1280 / 720, 0.1, 10);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  return camera;
}

/** Bounds of many projected points of the unit sphere under mvp (brute force). */
function sampledBounds(mvp: Matrix4): [number, number, number, number] {
  let x0 = Number.POSITIVE_INFINITY;
  let y0 = Number.POSITIVE_INFINITY;
  let x1 = Number.NEGATIVE_INFINITY;
  let y1 = Number.NEGATIVE_INFINITY;
  const p = new Vector3();
  const n = 200;
  for (let i = 0; i <= n; i++) {
    const theta = (Math.PI * i) / n;
    for (let j = 0; j < 2 * n; j++) {
      const phi = (Math.PI * j) / n;
      p.set(Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi)).applyMatrix4(
        mvp,
      );
      x0 = Math.min(x0, p.x);
      x1 = Math.max(x1, p.x);
      y0 = Math.min(y0, p.y);
      y1 = Math.max(y1, p.y);
    }
  }
  return [x0, y0, x1, y1];
}

describe('SphereImpostorMaterial', () => {
  it('includes the lighting chunk that ShadingMaterial includes (one named chunk; sources composed once, never rewritten)', () => {
    expect(lightingChunk).toContain('vec3 shadeColor(vec3 p, vec3 normal)');
    expect(lightingChunk).not.toContain('void main()');
    // The light count is the NUM_LIGHTS define: nothing is pasted into the source.
    expect(lightingChunk).not.toContain('LIGHT_COUNT_LITERAL');
    const light = new PhongLight();
    const material = new SphereImpostorMaterial({ lights: [light, new PhongLight()] });
    const shading = new ShadingMaterial({ lights: [light, new PhongLight()] });
    expect(material.fragmentShader).toContain(lightingChunk);
    expect(shading.fragmentShader).toContain(lightingChunk);
    expect(material.fragmentShader).toContain('gl_FragDepth');
    // The flat and gouraud stages light per vertex with the same chunk.
    shading.shading = 'gouraud';
    expect(shading.vertexShader).toContain(lightingChunk);
    expect(fragmentShader).toContain(lightingChunk);
    // Another light count is another define, with the same sources.
    const impostorSource = material.fragmentShader;
    material.phongLights = [light];
    shading.phongLights = [light, new PhongLight(), new PhongLight()];
    expect(material.fragmentShader).toBe(impostorSource);
    expect(shading.fragmentShader).toBe(fragmentShader);
    expect(shading.vertexShader).toBe(vertexShader);
    expect([material.defines.NUM_LIGHTS, shading.defines.NUM_LIGHTS]).toEqual([1, 3]);
  });

  it("takes ShadingMaterial's options and variants; shading is always per fragment", () => {
    const light = new PhongLight();
    const material = new SphereImpostorMaterial({
      lighting: 'blinn-phong',
      celBands: 4,
      ka: [0.1, 0.2, 0.3],
      shininess: 7,
      lights: [light],
    });
    expect(material).toBeInstanceOf(ShadingMaterial);
    expect(material.shading).toBe('phong');
    expect(material.defines).toMatchObject({
      LIGHTING_BLINN: '',
      CEL_BANDS: 4,
      NUM_LIGHTS: 1,
      SHADING_PHONG: '',
    });
    expect(material.shininess).toBe(7);
    expect(() => {
      material.shading = 'flat';
    }).toThrow(TypeError);
    expect(() => new SphereImpostorMaterial({ shading: 'gouraud' } as never)).toThrow(/'phong'/);
    // Changing the light count recompiles with the impostor's shaders, never ShadingMaterial's.
    material.phongLights = [light, new PhongLight(), new PhongLight()];
    expect(material.fragmentShader).toContain('impostorInverseMvp');
    expect(material.vertexShader).toContain('impostorBounds');
    expect(material.defines.NUM_LIGHTS).toBe(3);
  });

  it('fills the ray-casting uniforms per draw (lecture scene)', () => {
    const light = new PhongLight();
    light.position.set(-5, 10, 20);
    light.updateMatrixWorld();
    const material = new SphereImpostorMaterial({ lights: [light] });
    const impostor = new SphereImpostor(material);
    impostor.scale.set(2, 1, 2);
    impostor.updateMatrixWorld();
    const camera = lectureCamera();
    material.onBeforeRender(renderer, new Scene(), camera, impostor.geometry, impostor, null as never);
    const u = material.uniforms;
    const mvp = new Matrix4()
      .multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse)
      .multiply(impostor.matrixWorld);
    expect(u.impostorMvp.value.elements).toEqual(mvp.elements);
    // The inverse, times a power of two (see the extreme scales below).
    const product = new Matrix4().multiplyMatrices(u.impostorMvp.value, u.impostorInverseMvp.value);
    const factor = 2 ** Math.round(Math.log2(product.elements[0]));
    product.elements.forEach((v, i) => {
      expect(v / factor).toBeCloseTo(new Matrix4().elements[i], 12);
    });
    expect(u.impostorViewport.value.toArray()).toEqual([0, 0, 1280, 720]);
    // The lecture ellipsoid spans NDC x ±(2/√5)/(16/9) and y ±1/√5 (tangents from the eye), plus 1 px.
    const b = u.impostorBounds.value;
    expect(b.z).toBeCloseTo(2 / Math.sqrt(5) / (16 / 9) + 2 / 1280, 9);
    expect(b.w).toBeCloseTo(1 / Math.sqrt(5) + 2 / 720, 9);
    expect(b.x).toBeCloseTo(-b.z, 9);
    expect(b.y).toBeCloseTo(-b.w, 9);
    expect(material.uniforms.ambientTerm.value[0]).toBeCloseTo(0.6 * 0.2, 6);
  });

  it('a singular model matrix (zero scale) draws an empty quad, never NaN', () => {
    const material = new SphereImpostorMaterial();
    const impostor = new SphereImpostor(material);
    impostor.scale.set(1, 0, 1);
    impostor.updateMatrixWorld();
    material.onBeforeRender(
      renderer,
      new Scene(),
      lectureCamera(),
      impostor.geometry,
      impostor,
      null as never,
    );
    expect(material.uniforms.impostorBounds.value.toArray()).toEqual([2, 2, 2, 2]);
  });

  it('the quad geometry: 4 vertices, 2 triangles, 60 bytes, unit bounding sphere, flagged as a sphere', () => {
    const g = createImpostorQuad();
    expect(g.getAttribute('position').count).toBe(4);
    expect(g.index?.count).toBe(6);
    const index = g.index?.array ?? new Uint16Array(0);
    expect(g.getAttribute('position').array.byteLength + index.byteLength).toBe(60);
    expect(g.boundingSphere?.radius).toBe(1);
    expect(g.userData.isSphere).toBe(true);
  });
});

describe('projectedBounds', () => {
  it('property: contains every projected point of the ellipsoid and is tight to it', () => {
    fc.assert(
      fc.property(
        fc.tuple(...[0, 1, 2].map(() => fc.double({ min: 0.1, max: 3, noNaN: true }))),
        fc.tuple(...[0, 1, 2].map(() => fc.double({ min: -Math.PI, max: Math.PI, noNaN: true }))),
        fc.tuple(...[0, 1].map(() => fc.double({ min: -2, max: 2, noNaN: true }))),
        fc.boolean(),
        (scale, [rx, ry, rz], [tx, ty], orthographic) => {
          const camera = orthographic
            ? new OrthographicCamera(-4, 4, 3, -3, 0.1, 100)
            : new PerspectiveCamera(70, 4 / 3, 0.1, 100);
          camera.position.set(0.3, -0.2, 12);
          camera.lookAt(0, 0, 0);
          camera.updateMatrixWorld();
          const model = new Matrix4().compose(
            new Vector3(tx, ty, 0),
            new Quaternion().setFromEuler(new Euler(rx, ry, rz)),
            new Vector3(...scale),
          );
          const mvp = new Matrix4()
            .multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse)
            .multiply(model);
          const W = 800;
          const H = 600;
          const b = projectedBounds(mvp, W, H, new Vector4());
          const s = sampledBounds(mvp);
          // Contains: every sample (clamped to the viewport) lies inside the bounds.
          const c = (v: number) => Math.min(Math.max(v, -1), 1);
          expect(c(s[0])).toBeGreaterThanOrEqual(b.x - 1e-12);
          expect(c(s[1])).toBeGreaterThanOrEqual(b.y - 1e-12);
          expect(c(s[2])).toBeLessThanOrEqual(b.z + 1e-12);
          expect(c(s[3])).toBeLessThanOrEqual(b.w + 1e-12);
          // Tight: where not clamped, the bounds are the sampled extremes plus the 1 px margin, within the
          // sampling's own shortfall (the samples miss the true extreme by at most ~1e-4 of the extent).
          const tol = 1e-4 * Math.max(s[2] - s[0], s[3] - s[1]) + 1e-9;
          if (b.x > -1) expect(Math.abs(b.x + 2 / W - s[0])).toBeLessThan(tol);
          if (b.z < 1) expect(Math.abs(b.z - 2 / W - s[2])).toBeLessThan(tol);
          if (b.y > -1) expect(Math.abs(b.y + 2 / H - s[1])).toBeLessThan(tol);
          if (b.w < 1) expect(Math.abs(b.w - 2 / H - s[3])).toBeLessThan(tol);
        },
      ),
      { numRuns: 60 },
    );
  });

  it('covers the whole viewport when the eye is inside or beside the ellipsoid', () => {
    const camera = new PerspectiveCamera(90, 1, 0.1, 10);
    camera.position.set(0, 0, 0.5);
    camera.updateMatrixWorld();
    const mvp = new Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
    expect(projectedBounds(mvp, 100, 100, new Vector4()).toArray()).toEqual([-1, -1, 1, 1]);
    camera.position.set(1, 0, 0); // eye plane z = 0 through the sphere
    camera.updateMatrixWorld();
    mvp.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
    expect(projectedBounds(mvp, 100, 100, new Vector4()).toArray()).toEqual([-1, -1, 1, 1]);
  });
});

describe('SphereImpostorMaterial on an InstancedMesh', () => {
  type CompileShader = Parameters<SphereImpostorMaterial['onBeforeCompile']>[0];
  const compile = (material: SphereImpostorMaterial, instancing: boolean, instancingColor: boolean) => {
    const shader = { instancing, instancingColor, fragmentShader: material.fragmentShader } as CompileShader;
    material.onBeforeCompile(shader, renderer);
    return shader.fragmentShader;
  };

  it('tells the fragment stage of an instanced program (three defines USE_INSTANCING in the vertex stage only)', () => {
    const material = new SphereImpostorMaterial();
    const source = material.fragmentShader;
    expect(compile(material, false, false)).toBe(source); // one impostor: the program is unchanged
    expect(compile(material, true, false)).toBe(`#define IMPOSTOR_INSTANCED\n${source}`);
    expect(compile(material, true, true)).toBe(
      `#define IMPOSTOR_INSTANCED\n#define IMPOSTOR_INSTANCED_COLOR\n${source}`,
    );
    // Both stages read the instance: the vertex stage computes its bounds and inverse, the fragment casts.
    expect(material.vertexShader).toContain('impostorMvp * instanceMatrix');
    expect(source).toContain('flat in mat4 vImpostorInverse');
  });

  it('fills the view-projection matrix the instanced fragment stage needs, per draw', () => {
    const material = new SphereImpostorMaterial();
    const camera = lectureCamera();
    const quad = createImpostorQuad();
    const object = new SphereImpostor(material);
    object.updateMatrixWorld();
    material.onBeforeRender(renderer, new Scene(), camera, quad, object, null as never);
    const expected = new Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
    expect(material.uniforms.impostorViewProjection.value.elements).toEqual(expected.elements);
  });
});

describe('SphereImpostorMaterial at extreme scales (32-bit floats on the GPU)', () => {
  const draw = (scale: number, z: number, camera = lectureCamera()) => {
    const material = new SphereImpostorMaterial();
    const object = new SphereImpostor(material);
    object.scale.setScalar(scale);
    object.position.set(0, 0, z);
    object.updateMatrixWorld();
    material.onBeforeRender(renderer, new Scene(), camera, object.geometry, object, null as never);
    const mvp = new Matrix4()
      .multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse)
      .multiply(object.matrixWorld);
    return { u: material.uniforms, inverse: mvp.clone().invert() };
  };
  const wRow = (m: Matrix4) => Math.max(...[3, 7, 11, 15].map((i) => Math.abs(m.elements[i])));
  /** The whole lecture scene (camera, near and far included) scaled by `k`. */
  const scaledCamera = (k: number) => {
    const camera = new PerspectiveCamera(90, 1280 / 720, 0.1 * k, 10 * k);
    camera.position.set(0, 0, 3 * k);
    camera.updateMatrixWorld();
    return camera;
  };

  it('uploads the inverse P·V·M times the power of two that brings its w row into [1/√2, √2]: the same rays, the same rounding (every element scaled exactly); a zero inverse as it is', () => {
    for (const [scale, z, k] of [
      [1, 0, 1],
      [1e20, -3e20, 1],
      [1e-20, -1, 1],
      [1e15, 0, 1e15],
      [1e-18, 0, 1e-18],
    ] as const) {
      const { u, inverse } = draw(scale, z, scaledCamera(k));
      const uploaded = u.impostorInverseMvp.value;
      // three's invert gives the zero matrix where it finds none (three r179 for the 1e20 sphere): kept as it is.
      if (wRow(inverse) === 0) {
        expect(uploaded.elements).toEqual(inverse.elements);
        continue;
      }
      const w = wRow(uploaded);
      expect(w).toBeGreaterThanOrEqual(Math.SQRT1_2);
      expect(w).toBeLessThanOrEqual(Math.SQRT2);
      const factor = w / wRow(inverse);
      expect(Number.isInteger(Math.log2(factor))).toBe(true);
      expect(uploaded.elements).toEqual(inverse.elements.map((e) => e * factor));
    }
  });

  it('a whole scene scaled by 1e-18: the inverse P·V·M as uploaded stays within 32-bit range in the fragment stage (its w row was about 1e19, and products of w and xyz, squared in |d|², overflowed: nothing was drawn)', () => {
    const { u, inverse } = draw(1e-18, 0, scaledCamera(1e-18));
    expect(wRow(inverse)).toBeGreaterThan(1e18);
    for (const e of u.impostorInverseMvp.value.elements) expect(Math.abs(e)).toBeLessThan(100);
  });

  it('draws nothing when the eye is inside the sphere (its front surface is behind the eye)', () => {
    for (const scale of [10, 1e20])
      expect(draw(scale, 0).u.impostorBounds.value.toArray()).toEqual([2, 2, 2, 2]);
    expect(draw(1, 0).u.impostorBounds.value.x).toBeLessThan(1);
  });
});
