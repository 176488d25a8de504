import {
  computeNormalMatrix,
  FLAT_CORNERS,
  flatShadingGeometry,
  PhongLight,
  ShadingMaterial,
  shade,
} from '@shadelab/material';
import { OutlineMaterial } from '@shadelab/material/outline';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import fc from 'fast-check';
import {
  BufferAttribute,
  BufferGeometry,
  Color,
  Matrix3,
  Matrix4,
  Mesh,
  OrthographicCamera,
  PerspectiveCamera,
  Quaternion,
  Vector3,
  Vector4,
} from 'three';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { fuzzSeed, hostileNumbers, hostileValue, worksOrNamedError } from '../../../test-utils/fuzz.js';

// Issue 8: every constructor option and setter, fed hostile values, either works or throws a TypeError/RangeError
// naming the parameter, and no NaN or Infinity ever reaches a uniform (checked after the per-draw update that
// three runs before each draw, onBeforeRender).

const hostileNumber = hostileNumbers(1e4, 1);
const hostile = hostileValue(hostileNumber, {
  values: ['red', '#ff0000', 'not a colour', [1, 2]],
  extra: [fc.tuple(hostileNumber, hostileNumber, hostileNumber)],
});

const colour = fc.oneof(
  fc.tuple(
    fc.double({ min: 0, max: 2, noNaN: true }),
    fc.double({ min: 0, max: 2, noNaN: true }),
    fc.double({ min: 0, max: 2, noNaN: true }),
  ),
  // A number is a grey level (linear, the same on r, g and b); a hex colour is a CSS string. Three-style hex
  // numbers are large greys for a light or ka/kd/ks and refused by the outline (greys 0 … 1).
  fc.double({ min: 0, max: 2, noNaN: true }),
  fc.integer({ min: 0, max: 0xffffff }),
  fc.integer({ min: 0, max: 0xffffff }).map((hex) => `#${hex.toString(16).padStart(6, '0')}`),
  hostile,
);

const counts = { calls: 0, threw: 0, draws: 0 };
// Hostile input makes three warn (THREE.Color: Unknown color …) and the material report a colour edited in place
// (one console.error each): counted for the closing line instead of printed one by one.
const reported = { warn: 0, error: 0 };
beforeAll(() => {
  vi.spyOn(console, 'warn').mockImplementation(() => void reported.warn++);
  vi.spyOn(console, 'error').mockImplementation(() => void reported.error++);
});
afterAll(() => {
  vi.restoreAllMocks();
  console.log(
    `material fuzz: seed ${fuzzSeed()}, ${counts.calls} calls (${counts.threw} refused with a named TypeError/RangeError), ${counts.draws} draws with every uniform checked, ${reported.warn} warnings and ${reported.error} errors reported on the console`,
  );
});

/** Every number in every uniform is finite. */
function expectFiniteUniforms(uniforms: Record<string, { value: unknown }>): void {
  for (const [name, { value }] of Object.entries(uniforms)) {
    let numbers: ArrayLike<number> = [];
    if (typeof value === 'number') numbers = [value];
    else if (value instanceof Float32Array) numbers = value;
    else if (value instanceof Matrix3 || value instanceof Matrix4) numbers = value.elements;
    else if (value instanceof Vector4) numbers = value.toArray();
    else if (value instanceof Vector3) numbers = value.toArray();
    else if (value instanceof Color) numbers = value.toArray();
    for (let i = 0; i < numbers.length; i++) {
      if (!Number.isFinite(numbers[i])) expect.fail(`uniform ${name}[${i}] = ${numbers[i]}`);
    }
  }
}

const geometries = {
  smooth: new SubdivisionSphereGeometry({ level: 1 }),
  flat: new SubdivisionSphereGeometry({ level: 1, normals: 'flat' }),
};

/** What three does before a draw: update the matrices, then call the material's onBeforeRender. */
function draw(material: ShadingMaterial, mesh: Mesh, camera: PerspectiveCamera | OrthographicCamera): void {
  counts.draws++;
  mesh.geometry = material.shading === 'flat' ? geometries.flat : geometries.smooth;
  mesh.updateMatrixWorld(true);
  camera.updateMatrixWorld(true);
  for (const light of material.phongLights) light.updateMatrixWorld(true);
  material.onBeforeRender(null as never, null as never, camera, mesh.geometry, mesh, null as never);
  expectFiniteUniforms(material.uniforms as never);
}

const materialOptions = fc.record(
  {
    shading: fc.oneof(fc.constantFrom('flat', 'gouraud', 'phong'), hostile),
    lighting: fc.oneof(fc.constantFrom('phong', 'blinn-phong'), hostile),
    celBands: fc.oneof(fc.integer({ min: 0, max: 300 }), hostile),
    ka: colour,
    kd: colour,
    ks: colour,
    shininess: fc.oneof(fc.double({ min: 0, max: 1e4, noNaN: true }), hostile),
  },
  { requiredKeys: [] },
);

const lightOptions = fc.record(
  {
    ambient: colour,
    diffuse: colour,
    specular: colour,
    attenuation: fc.oneof(
      fc.record({ a: hostileNumber, b: hostileNumber, c: hostileNumber }, { requiredKeys: [] }),
      hostile,
    ),
  },
  { requiredKeys: [] },
);

const MATERIAL_NAMES = [
  'options',
  'shading',
  'lighting',
  'celBands',
  'ka',
  'kd',
  'ks',
  'shininess',
  'lights',
];
const LIGHT_NAMES = ['options', 'ambient', 'diffuse', 'specular', 'attenuation'];

describe('material fuzz (hostile values everywhere)', () => {
  it('new ShadingMaterial / PhongLight: built with finite uniforms, or a named error', () => {
    fc.assert(
      fc.property(
        fc.oneof({ weight: 9, arbitrary: materialOptions }, hostile),
        fc.array(fc.oneof({ weight: 9, arbitrary: lightOptions }, hostile), { maxLength: 3 }),
        (options, lightList) => {
          const lights: PhongLight[] = [];
          for (const o of lightList) {
            worksOrNamedError(counts, LIGHT_NAMES, () => lights.push(new PhongLight(o as never)));
          }
          let material: ShadingMaterial | undefined;
          const withLights =
            options !== null && typeof options === 'object' ? { ...options, lights } : options;
          if (
            !worksOrNamedError(
              counts,
              MATERIAL_NAMES,
              () => (material = new ShadingMaterial(withLights as never)),
            )
          )
            return;
          for (const [i, light] of lights.entries()) light.position.set(i, 2, 3);
          draw(material!, new Mesh(), new PerspectiveCamera());
          material!.dispose();
        },
      ),
      { numRuns: 400 },
    );
  });

  it('any sequence of setter assignments: each works or is refused by name, leaving the old value; uniforms stay finite', () => {
    const setters = [
      'shading',
      'lighting',
      'celBands',
      'ka',
      'kd',
      'ks',
      'shininess',
      'phongLights',
    ] as const;
    const lightSetters = ['ambient', 'diffuse', 'specular', 'attenuation'] as const;
    const step = fc.oneof(
      fc.tuple(fc.constant('material' as const), fc.constantFrom(...setters), fc.oneof(hostile, colour)),
      fc.tuple(fc.constant('light' as const), fc.constantFrom(...lightSetters), fc.oneof(hostile, colour)),
      fc.tuple(
        fc.constant('scale' as const),
        fc.constantFrom('x', 'y', 'z'),
        fc.constantFrom(0, 1e-20, 1e20, -1, 2),
      ),
      fc.tuple(
        fc.constant('camera' as const),
        fc.constantFrom('perspective', 'orthographic'),
        fc.constant(0),
      ),
      fc.tuple(fc.constant('lightAt' as const), fc.constant('x'), hostileNumber),
    );
    fc.assert(
      fc.property(fc.array(step, { minLength: 1, maxLength: 10 }), (steps) => {
        const light = new PhongLight({ attenuation: { a: 1, b: 0.1, c: 0 } });
        light.position.set(2, 3, 4);
        const material = new ShadingMaterial({ lights: [light] });
        const mesh = new Mesh();
        let camera: PerspectiveCamera | OrthographicCamera = new PerspectiveCamera();
        camera.position.set(0, 0, 5);
        for (const [kind, name, value] of steps) {
          if (kind === 'lightAt') {
            // A light the user put at NaN, infinity or beyond float32: that draw is refused by name.
            light.position.x = value as number;
            worksOrNamedError(counts, ['lights[0] world position'], () => draw(material, mesh, camera));
            expectFiniteUniforms(material.uniforms as never);
            light.position.x = 2;
          } else if (kind === 'scale') {
            mesh.scale[name as 'x'] = value as number;
          } else if (kind === 'camera') {
            camera = name === 'perspective' ? new PerspectiveCamera() : new OrthographicCamera();
            camera.position.set(0, 0, 5);
          } else {
            const target = (kind === 'material' ? material : light) as unknown as Record<string, unknown>;
            const before = JSON.stringify(
              target[name] instanceof Color ? (target[name] as Color).toArray() : target[name],
            );
            const label = name === 'phongLights' ? 'lights' : name;
            if (!worksOrNamedError(counts, [label], () => (target[name] = value))) {
              const after = JSON.stringify(
                target[name] instanceof Color ? (target[name] as Color).toArray() : target[name],
              );
              expect(after, `a refused ${name} keeps its value`).toBe(before);
            } else if (typeof value === 'number' && target[name] instanceof Color) {
              expect((target[name] as Color).toArray(), `${name} = ${value} is a grey level`).toEqual([
                value,
                value,
                value,
              ]);
            }
          }
          if (material.phongLights.length > 0 && !material.phongLights.every((l) => l instanceof PhongLight))
            return;
          draw(material, mesh, camera);
        }
        material.dispose();
      }),
      { numRuns: 400 },
    );
  });

  it('OutlineMaterial: finite uniforms or a named error', () => {
    fc.assert(
      fc.property(
        fc.oneof(
          fc.record(
            { thickness: fc.oneof(fc.double({ min: 0, max: 1, noNaN: true }), hostile), color: colour },
            { requiredKeys: [] },
          ),
          hostile,
        ),
        (options) => {
          let material: OutlineMaterial | undefined;
          if (
            worksOrNamedError(
              counts,
              ['options', 'thickness', 'color'],
              () => (material = new OutlineMaterial(options as never)),
            )
          ) {
            expectFiniteUniforms(material!.uniforms as never);
            material!.dispose();
          }
        },
      ),
      { numRuns: 300 },
    );
  });

  it('flatShadingGeometry: a flat-ready geometry with finite attributes, or a named error', () => {
    const geometry = (xyz: unknown, faces: unknown): unknown => {
      const g = new BufferGeometry();
      if (xyz instanceof Float32Array) g.setAttribute('position', new BufferAttribute(xyz, 3));
      if (Array.isArray(faces)) g.setIndex(faces);
      return g;
    };
    fc.assert(
      fc.property(
        fc.oneof(
          fc
            .integer({ min: 1, max: 8 })
            .chain((n) =>
              fc.tuple(
                fc.float32Array({ minLength: 3 * n, maxLength: 3 * n, noNaN: true, noDefaultInfinity: true }),
                fc.oneof(fc.constant(null), fc.array(fc.nat(n - 1), { maxLength: 30 })),
              ),
            )
            .map(([xyz, faces]) => geometry(xyz, faces)),
          fc.constant(geometry(null, null)),
          hostile,
        ),
        (g) => {
          let out: BufferGeometry | undefined;
          if (worksOrNamedError(counts, ['geometry'], () => (out = flatShadingGeometry(g as never)))) {
            for (const name of ['position', ...FLAT_CORNERS]) {
              expect(Array.from(out!.getAttribute(name).array).every(Number.isFinite), name).toBe(true);
            }
            expect(out!.index!.count).toBe(
              ((g as BufferGeometry).index ?? (g as BufferGeometry).getAttribute('position')).count,
            );
          }
        },
      ),
      { numRuns: 300 },
    );
  });

  it('computeNormalMatrix: finite for any finite model matrix, zero, tiny, huge and mirrored scales included', () => {
    const scale = fc.oneof(
      fc.constantFrom(0, 1e-20, 1e20, -1, 1e-300, 1e300),
      fc.double({ min: -1e3, max: 1e3, noNaN: true }),
    );
    fc.assert(
      fc.property(scale, scale, scale, fc.double({ min: 0, max: 6.3, noNaN: true }), (x, y, z, angle) => {
        const m = new Matrix4().compose(
          new Vector3(1, 2, 3),
          new Quaternion().setFromAxisAngle(new Vector3(1, 1, 0).normalize(), angle),
          new Vector3(x, y, z),
        );
        const n = computeNormalMatrix(m, new Matrix3());
        expect(n.elements.every(Number.isFinite), `${n.elements}`).toBe(true);
      }),
      { numRuns: 500 },
    );
  });

  it('shade (CPU): finite colours for every sane sample, extremes of the docs/design.md table included', () => {
    const unit = fc.tuple(
      fc.double({ min: -1, max: 1, noNaN: true }),
      fc.double({ min: -1, max: 1, noNaN: true }),
      fc.double({ min: -1, max: 1, noNaN: true }),
    );
    fc.assert(
      fc.property(
        unit,
        unit,
        fc.constantFrom(0, 1, 32, 1e4),
        fc.constantFrom(0, 2, 5),
        fc.constantFrom('phong', 'blinn-phong') as fc.Arbitrary<'phong' | 'blinn-phong'>,
        fc.boolean(),
        (position, normal, shininess, celBands, lighting, atSurface) => {
          const out = shade(
            { position, normal, eye: [0, 0, 5, 1] },
            { ka: [0.1, 0.1, 0.1], kd: [0.6, 0.3, 0.2], ks: [0.5, 0.5, 0.5], shininess, lighting, celBands },
            [
              {
                position: atSurface ? position : [2, 3, 4],
                ambient: [0.2, 0.2, 0.2],
                diffuse: [1, 1, 1],
                specular: [1, 1, 1],
                attenuation: { a: 0, b: 0, c: 1 },
              },
            ],
          );
          expect(out.every(Number.isFinite), `${out}`).toBe(true);
        },
      ),
      { numRuns: 500 },
    );
  });
});
