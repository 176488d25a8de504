import { SPHERE_BASES, SubdivisionSphereGeometry, subdivideSphere } from '@shadelab/sphere';
import fc from 'fast-check';
import {
  BufferGeometry,
  BufferGeometryLoader,
  Frustum,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  PerspectiveCamera,
  Raycaster,
  Sphere,
  Vector3,
} from 'three';
import { describe, expect, it } from 'vitest';

describe('SubdivisionSphereGeometry', () => {
  it('is a BufferGeometry of type SubdivisionSphereGeometry whose arrays are exactly subdivideSphere', () => {
    for (const base of SPHERE_BASES) {
      for (const options of [
        { level: 3, base, radius: 2 },
        { level: 2, base, normals: 'none' as const },
        { level: 2, base, normals: 'flat' as const },
        { level: 1, base, indexed: false },
      ]) {
        const geometry = new SubdivisionSphereGeometry(options);
        const mesh = subdivideSphere(options);
        expect(geometry).toBeInstanceOf(BufferGeometry);
        expect(geometry.type).toBe('SubdivisionSphereGeometry');
        expect(geometry.getAttribute('position').array).toEqual(mesh.positions);
        expect(geometry.getAttribute('position').itemSize).toBe(3);
        expect(geometry.getAttribute('normal')?.array).toEqual(mesh.normals);
        expect(geometry.getIndex()?.array).toEqual(mesh.indices);
      }
    }
  });

  it('keeps the resolved parameters (defaults applied): the material detects it by type and parameters.radius', () => {
    const geometry = new SubdivisionSphereGeometry({ radius: 3, normals: 'none' });
    expect(geometry.parameters).toEqual({
      level: 6,
      base: 'tetrahedron',
      radius: 3,
      normals: 'none',
      indexed: true,
      maxBytes: 512 * 1024 * 1024,
    });
    expect(geometry.hasAttribute('normal')).toBe(false);
    expect(new SubdivisionSphereGeometry({ level: 0, normals: 'flat' }).parameters.indexed).toBe(false);
  });

  it('index type: Uint16 while the vertices fit, Uint32 beyond 65,536 vertices', () => {
    const small = new SubdivisionSphereGeometry({ level: 7, base: 'tetrahedron', normals: 'none' }); // 32,770 vertices
    const large = new SubdivisionSphereGeometry({ level: 7, base: 'icosahedron', normals: 'none' }); // 163,842
    expect(small.getIndex()!.array).toBeInstanceOf(Uint16Array);
    expect(large.getIndex()!.array).toBeInstanceOf(Uint32Array);
    expect(large.getAttribute('position').count).toBe(163842);
  });

  it('has the exact bounding sphere (centre 0, radius), which three recomputation would only approach', () => {
    const geometry = new SubdivisionSphereGeometry({ level: 2, base: 'octahedron', radius: 5 });
    expect(geometry.boundingSphere).toEqual(new Sphere(new Vector3(0, 0, 0), 5));
    geometry.boundingSphere = null;
    geometry.computeBoundingSphere();
    expect(geometry.boundingSphere).toEqual(new Sphere(new Vector3(0, 0, 0), 5));
    // three's generic computation from the vertices agrees within float32 rounding.
    const generic = new BufferGeometry();
    generic.setAttribute('position', geometry.getAttribute('position'));
    generic.computeBoundingSphere();
    expect(generic.boundingSphere!.radius).toBeCloseTo(5, 5);
  });

  it('clone and copy keep the arrays and the parameters, without sharing them', () => {
    const geometry = new SubdivisionSphereGeometry({ level: 3, base: 'icosahedron', radius: 1.5 });
    const clone = geometry.clone();
    expect(clone).toBeInstanceOf(SubdivisionSphereGeometry);
    expect(clone.type).toBe('SubdivisionSphereGeometry');
    expect(clone.parameters).toEqual(geometry.parameters);
    expect(clone.parameters).not.toBe(geometry.parameters);
    expect(clone.getAttribute('position').array).toEqual(geometry.getAttribute('position').array);
    expect(clone.getAttribute('position').array).not.toBe(geometry.getAttribute('position').array);
    expect(clone.getIndex()!.array).toEqual(geometry.getIndex()!.array);
    expect(clone.boundingSphere).toEqual(geometry.boundingSphere);

    const target = new SubdivisionSphereGeometry({ level: 0 });
    target.copy(geometry);
    expect(target.parameters).toEqual(geometry.parameters);
    expect(target.getAttribute('normal').array).toEqual(geometry.getAttribute('normal').array);
    expect(target.boundingSphere!.radius).toBe(1.5);
  });

  it('round-trips through toJSON / fromJSON by its parameters', () => {
    const geometry = new SubdivisionSphereGeometry({
      level: 2,
      base: 'octahedron',
      radius: 2,
      maxBytes: Infinity,
    });
    const json = JSON.parse(JSON.stringify(geometry.toJSON()));
    expect(json.type).toBe('SubdivisionSphereGeometry');
    const rebuilt = SubdivisionSphereGeometry.fromJSON(json);
    expect(rebuilt.parameters).toEqual({ ...geometry.parameters, maxBytes: 512 * 1024 * 1024 });
    expect(rebuilt.getAttribute('position').array).toEqual(geometry.getAttribute('position').array);
    // three's generic loader still reads the arrays of a non-parametric copy.
    const plain = new BufferGeometry().copy(geometry);
    const loaded = new BufferGeometryLoader().parse(plain.toJSON());
    expect(loaded.getAttribute('position').array).toEqual(geometry.getAttribute('position').array);
  });

  it('works with three: rays from outside hit front faces at the radius (within the error), from inside none; frustum culling uses it', () => {
    const radius = 2;
    const level = 4;
    const mesh = new Mesh(
      new SubdivisionSphereGeometry({ level, base: 'icosahedron', radius }),
      new MeshBasicMaterial(),
    );
    const raycaster = new Raycaster();
    fc.assert(
      fc.property(
        fc.double({ min: -1, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }),
        (z, phi) => {
          const r = Math.sqrt(1 - z * z);
          const direction = new Vector3(r * Math.cos(phi), r * Math.sin(phi), z);
          raycaster.set(direction.clone().multiplyScalar(10), direction.clone().negate());
          // The material draws front faces only, so a hit from outside means outward winding …
          const hits = raycaster.intersectObject(mesh);
          expect(hits.length).toBeGreaterThanOrEqual(1);
          expect(hits[0].face!.normal.dot(direction)).toBeGreaterThan(0);
          // … and a ray from the centre outwards meets only back faces: no hit.
          raycaster.set(new Vector3(0, 0, 0), direction);
          expect(raycaster.intersectObject(mesh)).toHaveLength(0);
          const distance = hits[0].point.length();
          expect(distance).toBeLessThanOrEqual(radius * (1 + 1e-6));
          expect(distance).toBeGreaterThanOrEqual(radius * (1 - 0.0012)); // sphereError(icosahedron, 4) ≈ 0.00114
        },
      ),
      { numRuns: 40 },
    );
    const camera = new PerspectiveCamera(50, 1, 0.1, 100);
    camera.position.set(0, 0, 10);
    camera.updateMatrixWorld();
    const frustum = new Frustum().setFromProjectionMatrix(
      new Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse),
    );
    expect(frustum.intersectsObject(mesh)).toBe(true);
    mesh.position.set(100, 0, 0);
    mesh.updateMatrixWorld();
    expect(frustum.intersectsObject(mesh)).toBe(false);
  });

  it('validates like subdivideSphere, naming the class', () => {
    expect(() => new SubdivisionSphereGeometry({ level: -1 })).toThrow(RangeError);
    expect(() => new SubdivisionSphereGeometry({ level: -1 })).toThrow(/SubdivisionSphereGeometry: level/);
    expect(() => new SubdivisionSphereGeometry({ radius: 0 })).toThrow(/radius/);
    expect(() => new SubdivisionSphereGeometry({ level: 11, base: 'icosahedron' })).toThrow(
      /bytes.*maxBytes/,
    );
    // The memory error names the class too, not the function it calls.
    expect(() => new SubdivisionSphereGeometry({ level: 11, base: 'icosahedron' })).toThrow(
      /^SubdivisionSphereGeometry: level 11 of the icosahedron .* needs about 2\.01 GB \(2013265968 bytes\)/,
    );
    expect(() => new SubdivisionSphereGeometry({ level: 11, base: 'icosahedron' })).not.toThrow(
      /subdivideSphere/,
    );
  });
});
