import { eyeOf, flatShadingGeometry, PhongLight, type Shading, ShadingMaterial } from '@shadelab/material';
import fc from 'fast-check';
import {
  BackSide,
  BufferGeometry,
  Color,
  DataTexture,
  Float32BufferAttribute,
  Group,
  IcosahedronGeometry,
  type Matrix3,
  Mesh,
  OrthographicCamera,
  PerspectiveCamera,
  PointLight,
  Scene,
  Vector2,
  Vector3,
  Vector4,
  type WebGLRenderer,
} from 'three';
import { describe, expect, it, vi } from 'vitest';

const renderer = {} as WebGLRenderer;

/** What three does per draw: onBeforeRender, then (on version change) a program lookup by defines. */
function draw(material: ShadingMaterial, mesh: Mesh, camera = new PerspectiveCamera(90, 1, 0.1, 10)): void {
  mesh.updateMatrixWorld();
  camera.updateMatrixWorld();
  material.onBeforeRender(renderer, new Scene(), camera, mesh.geometry, mesh, new Group());
}

function sphere(): BufferGeometry {
  const g = new IcosahedronGeometry(1, 2); // non-indexed, normals = positions
  g.deleteAttribute('normal');
  g.userData.isSphere = true;
  return g;
}

describe('ShadingMaterial options', () => {
  it('defaults: phong × phong, no cel, the documented colours and shininess', () => {
    const m = new ShadingMaterial();
    expect([m.shading, m.lighting, m.celBands, m.shininess]).toEqual(['phong', 'phong', 0, 32]);
    expect(m.ka.equals(new Color(0.6, 0.35, 0.2))).toBe(true);
    expect(m.kd.equals(new Color(0.6, 0.35, 0.2))).toBe(true);
    expect(m.ks.equals(new Color(0.5, 0.5, 0.5))).toBe(true);
    expect(m.phongLights).toEqual([]);
    expect(m.lights).toBe(false); // three's own lights stay off
    expect(m.defines).toEqual({ SHADING_PHONG: '', CEL_BANDS: 0, NUM_LIGHTS: 0 });
  });

  it('refuses bad values with errors naming the parameter, the value and the range', () => {
    const m = new ShadingMaterial();
    expect(() => {
      m.shading = 'smooth' as Shading;
    }).toThrow(/ShadingMaterial\.shading must be one of 'flat', 'gouraud', 'phong', got "smooth"/);
    expect(() => {
      m.lighting = 'cel' as never;
    }).toThrow(TypeError);
    for (const bad of [1, -2, 2.5, 256, Number.NaN]) {
      expect(() => {
        m.celBands = bad;
      }).toThrow(
        new RangeError(`ShadingMaterial.celBands must be 0 (off) or an integer in 2 … 255, got ${bad}`),
      );
    }
    for (const bad of [-1, Number.NaN, Number.POSITIVE_INFINITY]) {
      expect(() => {
        m.shininess = bad;
      }).toThrow(new RangeError(`ShadingMaterial.shininess must be a finite number ≥ 0, got ${bad}`));
    }
    expect(() => {
      m.kd = [1, Number.NaN, 0];
    }).toThrow(/ShadingMaterial\.kd must have finite channels ≥ 0/);
    expect(() => {
      m.ks = [-0.1, 0, 0];
    }).toThrow(RangeError);
    expect(() => {
      m.ka = 'not-a-colour';
    }).toThrow(TypeError);
    expect(() => {
      m.phongLights = [new Mesh() as never];
    }).toThrow(/ShadingMaterial\.lights\[0\] must be a PhongLight/);
    expect(() => new ShadingMaterial({ celBands: 1 })).toThrow(RangeError);
    // Failed sets change nothing.
    expect([m.shading, m.celBands, m.shininess]).toEqual(['phong', 0, 32]);
    expect(m.kd.equals(new Color(0.6, 0.35, 0.2))).toBe(true);
  });

  it('accepts CSS colours as sRGB, tuples and Colors as linear (greys: ColorInput.test.ts)', () => {
    const m = new ShadingMaterial({ ka: '#ffffff', kd: [0.25, 0.5, 1], ks: new Color(0.1, 0.2, 0.3) });
    expect(m.ka.toArray()).toEqual([1, 1, 1]);
    expect(m.kd.toArray()).toEqual([0.25, 0.5, 1]);
    expect(m.ks.toArray()).toEqual([0.1, 0.2, 0.3]);
    m.ka = '#808080';
    expect(m.ka.r).toBeCloseTo(0.2158605, 6); // sRGB 128 → linear
  });
});

describe('ShadingMaterial variants (defines) and recompiles', () => {
  it('every shading × lighting × cel has its defines; needsUpdate only when they change', () => {
    const m = new ShadingMaterial();
    let version = m.version;
    m.shininess = 5;
    m.kd = [0.1, 0.1, 0.1];
    expect(m.version).toBe(version); // uniforms only
    m.shading = 'phong';
    m.lighting = 'phong';
    m.celBands = 0;
    expect(m.version).toBe(version); // same variant
    m.lighting = 'blinn-phong';
    expect(m.version).toBe(++version);
    expect(m.defines.LIGHTING_BLINN).toBe('');
    m.shading = 'gouraud';
    expect(m.version).toBe(++version);
    expect(m.defines.SHADING_GOURAUD).toBe('');
    expect(m.defines.SHADING_PHONG).toBeUndefined();
    m.celBands = 3;
    expect(m.version).toBe(++version);
    expect(m.defines.CEL_BANDS).toBe(3);
  });

  it('lights, attenuation and analytic sphere normals enter the variant from the draw', () => {
    const light = new PhongLight();
    const m = new ShadingMaterial({ lights: [light, new PhongLight()] });
    const mesh = new Mesh(sphere(), m);
    draw(m, mesh);
    expect(m.defines).toEqual({ SHADING_PHONG: '', CEL_BANDS: 0, NUM_LIGHTS: 2, SPHERE_NORMALS: '' });
    const version = m.version;
    draw(m, mesh);
    expect(m.version).toBe(version);
    light.attenuation = { a: 1, b: 0.1 };
    draw(m, mesh);
    expect(m.defines.USE_ATTENUATION).toBe('');
    expect(m.version).toBe(version + 1);
    draw(m, new Mesh(new IcosahedronGeometry(1, 1), m)); // has normals: attribute, not analytic
    expect(m.defines.SPHERE_NORMALS).toBeUndefined();
    m.shading = 'flat';
    draw(m, mesh);
    expect(m.defines.SPHERE_NORMALS).toBeUndefined(); // flat reads positions only
  });

  it('1,000 random option flips touch at most the 3·2·2 variants, and bump the version only on change', () => {
    fc.assert(
      fc.property(
        fc.array(
          fc.record({
            shading: fc.constantFrom<Shading>('flat', 'gouraud', 'phong'),
            lighting: fc.constantFrom('phong' as const, 'blinn-phong' as const),
            celBands: fc.constantFrom(0, 4),
          }),
          { minLength: 1000, maxLength: 1000 },
        ),
        (flips) => {
          const m = new ShadingMaterial();
          const variants = new Set<string>();
          let changes = 0;
          let last = JSON.stringify(m.defines);
          for (const f of flips) {
            Object.assign(m, f);
            const key = JSON.stringify(m.defines);
            if (key !== last) changes++;
            last = key;
            variants.add(key);
          }
          expect(variants.size).toBeLessThanOrEqual(12);
          // Each setter bumps at most once per actual change of the defines.
          expect(m.version).toBeLessThanOrEqual(1 + 3 * changes);
        },
      ),
      { numRuns: 5 },
    );
  });

  it('flat shading takes a flatShadingGeometry, a soup or a plain indexed one (derivative normals); gouraud and phong need normals unless a flagged sphere', () => {
    const indexed = new BufferGeometry();
    indexed.setAttribute('position', new Float32BufferAttribute([0, 0, 0, 1, 0, 0, 0, 1, 0], 3));
    indexed.setIndex([0, 1, 2]);
    const m = new ShadingMaterial({ shading: 'flat' });
    // A plain indexed geometry: no preparation, per-fragment lighting with the derivative face normal.
    draw(m, new Mesh(indexed, m));
    expect(m.defines.FLAT_DERIVATIVES).toBe('');
    expect(m.defines.FLAT_CORNERS).toBeUndefined();
    expect(m.uniforms.facePositions.value).toBeNull();
    // The indexed way: each face's last vertex carries the face (FLAT_CORNERS), no texture.
    draw(m, new Mesh(flatShadingGeometry(indexed), m));
    expect(m.defines.FLAT_CORNERS).toBe('');
    expect(m.defines.FLAT_DERIVATIVES).toBeUndefined();
    expect(m.uniforms.facePositions.value).toBeNull();
    // Made for WebGPU's provoking vertex (the first): WebGL's is the last, so derivatives, and one warning.
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    const forWebGPU = flatShadingGeometry(indexed, { provokingVertex: 'first' });
    draw(m, new Mesh(forWebGPU, m));
    draw(m, new Mesh(forWebGPU, m));
    expect(m.defines.FLAT_DERIVATIVES).toBe('');
    expect(m.defines.FLAT_CORNERS).toBeUndefined();
    expect(warn.mock.calls.map((c) => String(c[0]))).toEqual([
      expect.stringMatching(/provokingVertex 'first' \(WebGPU's\); WebGL's is the last/),
    ]);
    warn.mockRestore();
    const bare = indexed.toNonIndexed();
    draw(m, new Mesh(bare, m)); // the soup way: positions only, fetched from a texture
    expect(m.defines.FLAT_CORNERS).toBeUndefined();
    expect(m.uniforms.facePositions.value).not.toBeNull();
    m.shading = 'gouraud';
    expect(() => draw(m, new Mesh(bare, m))).toThrow(/gouraud shading needs a normal attribute/);
  });
});

describe('ShadingMaterial per-draw uniforms', () => {
  it('lights: world positions (parented, moved), kd·Id, ks·Is, Σ ka·Ia; no NaN', () => {
    const parent = new Group();
    parent.position.set(1, 2, 3);
    const light = new PhongLight({
      ambient: [0.5, 0.5, 0.5],
      diffuse: [1, 0.5, 0.25],
      specular: [0.2, 0.4, 0.8],
    });
    light.position.set(-5, 10, 20);
    parent.add(light);
    parent.updateMatrixWorld();
    const other = new PhongLight();
    other.updateMatrixWorld();
    const m = new ShadingMaterial({
      ka: [1, 1, 1],
      kd: [0.5, 0.5, 0.5],
      ks: [1, 1, 1],
      lights: [light, other],
    });
    draw(m, new Mesh(sphere(), m));
    const u = m.uniforms;
    expect(Array.from(u.lightPosition.value)).toEqual([-4, 12, 23, 0, 0, 0]);
    expect(Array.from(u.lightDiffuse.value as Float32Array).slice(0, 3)).toEqual([0.5, 0.25, 0.125]);
    expect(Array.from(u.lightSpecular.value as Float32Array).slice(0, 3)).toEqual(
      [0.2, 0.4, 0.8].map(Math.fround),
    );
    expect(Array.from(u.ambientTerm.value as Float32Array)).toEqual([0.7, 0.7, 0.7].map(Math.fround));
    parent.position.x += 10;
    parent.updateMatrixWorld();
    draw(m, new Mesh(sphere(), m));
    expect(u.lightPosition.value[0]).toBe(6);
    expect(m.uniformsNeedUpdate).toBe(true);
  });

  it('a colour edited in place is reported once (console.error), drawn with the last good uniforms, again after a fix', () => {
    const errors: string[] = [];
    const spy = vi.spyOn(console, 'error').mockImplementation((message: string) => {
      errors.push(message);
    });
    try {
      const light = new PhongLight();
      light.updateMatrixWorld();
      const m = new ShadingMaterial({ lights: [light] });
      const mesh = new Mesh(sphere(), m);
      draw(m, mesh);
      const good = Array.from(m.uniforms.lightDiffuse.value as Float32Array);
      const goodAmbient = Array.from(m.uniforms.ambientTerm.value as Float32Array);
      // React Three Fiber's kd={[NaN, -1, 0]} writes into the Color: the setter never sees it.
      m.kd.setRGB(Number.NaN, -1, 0);
      for (let frame = 0; frame < 190; frame++) expect(() => draw(m, mesh)).not.toThrow();
      expect(errors).toEqual([
        'ShadingMaterial.kd must have finite channels ≥ 0 (linear RGB), got Color(NaN, -1, 0) (edited in place; drawing with the last valid values)',
      ]);
      expect(Array.from(m.uniforms.lightDiffuse.value as Float32Array)).toEqual(good);
      expect(Array.from(m.uniforms.ambientTerm.value as Float32Array)).toEqual(goodAmbient);
      // Fixed: drawn with the new values, silently.
      m.kd.setRGB(0.5, 0.5, 0.5);
      draw(m, mesh);
      expect(Array.from(m.uniforms.lightDiffuse.value as Float32Array)).toEqual([0.5, 0.5, 0.5]);
      expect(errors).toHaveLength(1);
      // A PhongLight colour edited in place: reported once, naming the light.
      light.diffuse.r = Number.NaN;
      for (let frame = 0; frame < 10; frame++) draw(m, mesh);
      expect(errors).toHaveLength(2);
      expect(errors[1]).toMatch(
        /^ShadingMaterial\.lights\[0\]: PhongLight\.diffuse must have finite channels ≥ 0 \(linear RGB\), got Color\(NaN, 1, 1\)/,
      );
      expect(Array.from(m.uniforms.lightDiffuse.value as Float32Array)).toEqual([0.5, 0.5, 0.5]);
      light.diffuse.r = 1;
      draw(m, mesh);
      // The same bad value again after a fix is a new problem: reported again.
      light.diffuse.r = Number.NaN;
      draw(m, mesh);
      draw(m, mesh);
      expect(errors).toHaveLength(3);
      // Too large and non-finite positions too; lights added while bad are off (zeros), never NaN.
      light.diffuse.r = 1;
      m.ks.g = 1e30;
      const late = new PhongLight();
      late.updateMatrixWorld();
      m.phongLights = [light, late];
      draw(m, mesh);
      expect(errors[3]).toMatch(/ShadingMaterial\.ks must have channels at most 1e18/);
      expect(Array.from(m.uniforms.lightDiffuse.value as Float32Array)).toEqual([0, 0, 0, 0, 0, 0]);
    } finally {
      spy.mockRestore();
    }
  });

  it('the normal matrix is the robust one of the world matrix (finite for a zero scale)', () => {
    const m = new ShadingMaterial();
    const mesh = new Mesh(sphere(), m);
    mesh.scale.set(2, 1, 0);
    draw(m, mesh);
    const n: Matrix3 = m.uniforms.shadingNormalMatrix.value;
    expect(n.elements).toEqual([0, 0, 0, 0, 0, 0, 0, 0, 1]);
  });
});

describe("three's lights", () => {
  it('compile only when the scene has one: SHADING_THREE_LIGHTS and three’s lights flag; found once per frame', () => {
    const m = new ShadingMaterial();
    const mesh = new Mesh(sphere(), m);
    const scene = new Scene();
    scene.add(mesh);
    const frame = { info: { render: { frame: 1 } } } as unknown as WebGLRenderer;
    const at = () => {
      mesh.updateMatrixWorld();
      m.onBeforeRender(frame, scene, new PerspectiveCamera(), mesh.geometry, mesh, new Group());
    };
    at();
    expect(m.defines.SHADING_THREE_LIGHTS).toBeUndefined();
    expect(m.lights).toBe(false);
    const point = new PointLight();
    scene.add(point);
    at(); // the same frame: the scene was already searched
    expect(m.defines.SHADING_THREE_LIGHTS).toBeUndefined();
    frame.info.render.frame++;
    const version = m.version;
    at();
    expect(m.defines.SHADING_THREE_LIGHTS).toBe('');
    expect(m.lights).toBe(true);
    expect(m.version).toBe(version + 1);
    point.visible = false; // three skips an invisible light: so does the search
    frame.info.render.frame++;
    at();
    expect(m.lights).toBe(false);
    // three's light uniforms are there for three to fill (ambientLightColor, pointLights, …).
    expect(Object.keys(m.uniforms)).toEqual(
      expect.arrayContaining(['ambientLightColor', 'pointLights', 'spotLights']),
    );
  });
});

describe('PhongLights found in the scene', () => {
  it('light the material without being listed; a non-empty list restricts the set; searched once per frame', () => {
    const m = new ShadingMaterial();
    const mesh = new Mesh(sphere(), m);
    const a = new PhongLight({ diffuse: 0.5 });
    a.position.set(1, 2, 3);
    const b = new PhongLight({ attenuation: { a: 1, b: 0.5, c: 0 } });
    b.position.set(-4, 0, 0);
    const hidden = new PhongLight();
    hidden.visible = false; // three skips it: so does the search
    const scene = new Scene();
    scene.add(mesh, a, new Group().add(b), hidden);
    scene.updateMatrixWorld();
    const frame = { info: { render: { frame: 7 } } } as unknown as WebGLRenderer;
    const at = () =>
      m.onBeforeRender(frame, scene, new PerspectiveCamera(), mesh.geometry, mesh, new Group());
    at();
    expect(m.defines.NUM_LIGHTS).toBe(2);
    expect(m.defines.USE_ATTENUATION).toBe('');
    expect(Array.from(m.uniforms.lightPosition.value as Float32Array)).toEqual([1, 2, 3, -4, 0, 0]);
    scene.add(new PhongLight()); // the same frame: the scene was already searched
    at();
    expect(m.defines.NUM_LIGHTS).toBe(2);
    frame.info.render.frame++;
    at();
    expect(m.defines.NUM_LIGHTS).toBe(3);
    m.phongLights = [a]; // an explicit list restricts the set
    at();
    expect(m.defines.NUM_LIGHTS).toBe(1);
    expect(m.defines.USE_ATTENUATION).toBeUndefined();
    expect(Array.from(m.uniforms.lightDiffuse.value as Float32Array)).toEqual(
      [0.3, 0.175, 0.1].map(Math.fround),
    );
    m.phongLights = []; // empty again: the scene's
    at();
    expect(m.defines.NUM_LIGHTS).toBe(3);
  });
});

describe('eyeOf', () => {
  it('is the camera position for a perspective camera', () => {
    const camera = new PerspectiveCamera(60, 1.5, 0.1, 100);
    camera.position.set(1, 2, 3);
    camera.lookAt(-4, 0, 1);
    camera.updateMatrixWorld();
    const e = eyeOf(camera, new Vector4());
    expect(e.w).toBe(1);
    expect(e.x).toBeCloseTo(1, 9);
    expect(e.y).toBeCloseTo(2, 9);
    expect(e.z).toBeCloseTo(3, 9);
  });

  it('is the camera’s backward (+w) axis for an orthographic camera', () => {
    const camera = new OrthographicCamera(-2, 3, 1, -1, 0.5, 50);
    camera.position.set(5, 5, 5);
    camera.lookAt(0, 0, 0);
    camera.updateMatrixWorld();
    const e = eyeOf(camera, new Vector4());
    expect(e.w).toBe(0);
    const back = new Vector3(1, 1, 1).normalize();
    expect(e.x).toBeCloseTo(back.x, 12);
    expect(e.y).toBeCloseTo(back.y, 12);
    expect(e.z).toBeCloseTo(back.z, 12);
  });
});

describe('PhongLight', () => {
  it('defaults to the lecture’s light and validates', () => {
    const l = new PhongLight();
    expect(l.ambient.toArray()).toEqual([0.2, 0.2, 0.2]);
    expect(l.diffuse.toArray()).toEqual([1, 1, 1]);
    expect(l.specular.toArray()).toEqual([0.8, 0.8, 0.8]);
    expect(l.attenuation).toEqual({ a: 1, b: 0, c: 0 });
    expect(l.attenuates).toBe(false);
    expect(() => {
      l.attenuation = { a: 0, b: 0, c: 0 };
    }).toThrow(/a = b = c = 0/);
    expect(() => {
      l.attenuation = { b: -1 };
    }).toThrow(new RangeError('PhongLight.attenuation.b must be a finite number ≥ 0, got -1'));
    expect(() => {
      l.attenuation = { c: Number.POSITIVE_INFINITY };
    }).toThrow(/attenuation\.c/);
    expect(() => new PhongLight({ specular: [0, 0, Number.NaN] })).toThrow(/PhongLight\.specular/);
    l.attenuation = { a: 0, c: 2 };
    expect(l.attenuation).toEqual({ a: 0, b: 0, c: 2 });
    expect(l.attenuates).toBe(true);
  });

  it('clone keeps colours and attenuation', () => {
    const l = new PhongLight({ diffuse: [0.1, 0.2, 0.3], attenuation: { b: 0.5 } });
    l.position.set(1, 2, 3);
    const c = l.clone();
    expect(c.diffuse.toArray()).toEqual([0.1, 0.2, 0.3]);
    expect(c.attenuation).toEqual({ a: 1, b: 0.5, c: 0 });
    expect(c.position.toArray()).toEqual([1, 2, 3]);
    expect(c.diffuse).not.toBe(l.diffuse);
  });

  it('a material clone keeps its options', () => {
    const light = new PhongLight();
    const m = new ShadingMaterial({
      shading: 'flat',
      lighting: 'blinn-phong',
      celBands: 3,
      shininess: 7,
      lights: [light],
    });
    const c = m.clone();
    expect([c.shading, c.lighting, c.celBands, c.shininess]).toEqual(['flat', 'blinn-phong', 3, 7]);
    expect(c.phongLights).toEqual([light]);
    expect(c.defines).toEqual(m.defines);
  });
});

describe('ShadingMaterial surface (three’s map, vertexColors, emissive, opacity, alphaTest, alphaMap)', () => {
  const texture = () => new DataTexture(new Uint8Array(4), 1, 1);

  it('options and properties by three’s names; bad values throw naming the parameter, the value and the range', () => {
    const map = texture();
    const m = new ShadingMaterial({
      map,
      vertexColors: true,
      emissive: [0.1, 0.2, 0.3],
      opacity: 0.5,
      transparent: true,
      alphaTest: 0.25,
    });
    expect(m.map).toBe(map);
    expect(m.vertexColors).toBe(true);
    expect(m.emissive.toArray()).toEqual([0.1, 0.2, 0.3]);
    expect([m.opacity, m.transparent, m.alphaTest]).toEqual([0.5, true, 0.25]);
    expect(() => new ShadingMaterial({ opacity: 1.5 })).toThrow(
      new RangeError('ShadingMaterial.opacity must be in 0 … 1, got 1.5'),
    );
    expect(() => {
      m.opacity = Number.NaN;
    }).toThrow(new RangeError('ShadingMaterial.opacity must be in 0 … 1, got NaN'));
    expect(() => {
      m.alphaTest = -0.1;
    }).toThrow(new RangeError('ShadingMaterial.alphaTest must be in 0 … 1, got -0.1'));
    expect(() => new ShadingMaterial({ emissive: [-1, 0, 0] })).toThrow(
      /ShadingMaterial.emissive must have finite channels ≥ 0/,
    );
    expect(() => new ShadingMaterial({ map: 'brick.png' as never })).toThrow(
      new TypeError('ShadingMaterial.map must be a THREE.Texture or null, got "brick.png"'),
    );
    expect([m.opacity, m.alphaTest]).toEqual([0.5, 0.25]); // unchanged by the refused values
    // clone() copies the surface (sharing the textures, as three does).
    const c = m.clone();
    expect([c.map, c.opacity, c.alphaTest, c.transparent]).toEqual([map, 0.5, 0.25, true]);
    expect(c.emissive.toArray()).toEqual([0.1, 0.2, 0.3]);
  });

  it('per draw: the uniforms three refreshes for its own materials (map and its uv transform, opacity, alphaTest, emissive)', () => {
    const m = new ShadingMaterial({ shading: 'gouraud' });
    const mesh = new Mesh(sphere(), m);
    draw(m, mesh);
    expect(m.defines.SHADING_EMISSIVE).toBeUndefined();
    const map = texture();
    map.offset.set(0.25, 0.5);
    m.map = map;
    m.alphaMap = texture();
    m.opacity = 0.4;
    m.alphaTest = 0.3;
    m.emissive.setRGB(0.1, 0, 0);
    const version = m.version;
    draw(m, mesh);
    expect(m.uniforms.map.value).toBe(map);
    expect(m.uniforms.alphaMap.value).toBe(m.alphaMap);
    expect(m.uniforms.mapTransform.value.elements).toEqual(map.matrix.elements);
    expect(m.uniforms.mapTransform.value.elements[6]).toBeCloseTo(0.25, 12);
    expect([m.uniforms.opacity.value, m.uniforms.alphaTest.value]).toEqual([0.4, 0.3]);
    expect(m.uniforms.emissive.value.toArray()).toEqual([0.1, 0, 0]);
    expect(m.defines.SHADING_EMISSIVE).toBe('');
    expect(m.version).toBeGreaterThan(version); // a new program: the map, alpha map, alpha test and emissive
    const again = m.version;
    draw(m, mesh);
    expect(m.version).toBe(again); // nothing changed: no recompile
    // An emissive edited in place to a bad value is reported once, drawn with the last good one.
    const error = vi.spyOn(console, 'error').mockImplementation(() => {});
    m.emissive.setRGB(Number.NaN, 0, 0);
    draw(m, mesh);
    draw(m, mesh);
    expect(error).toHaveBeenCalledTimes(1);
    expect(String(error.mock.calls[0][0])).toMatch(/^ShadingMaterial.emissive must have finite channels/);
    expect(m.uniforms.emissive.value.toArray()).toEqual([0.1, 0, 0]);
    error.mockRestore();
  });
});

describe('ShadingMaterial normalMap', () => {
  it('uniforms as three refreshes them (BackSide turns the scale round); one warning for a shading without per-fragment normals', () => {
    const normalMap = new DataTexture(new Uint8Array([128, 128, 255, 255]), 1, 1);
    const m = new ShadingMaterial({ normalMap, normalScale: new Vector2(0.5, -2) });
    const mesh = new Mesh(sphere(), m);
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    draw(m, mesh);
    expect(m.uniforms.normalMap.value).toBe(normalMap);
    expect(m.uniforms.normalScale.value.toArray()).toEqual([0.5, -2]);
    m.side = BackSide;
    draw(m, mesh);
    expect(m.uniforms.normalScale.value.toArray()).toEqual([-0.5, 2]);
    expect(warn).not.toHaveBeenCalled();
    m.shading = 'gouraud';
    draw(m, mesh);
    draw(m, mesh);
    expect(warn).toHaveBeenCalledTimes(1);
    expect(warn.mock.calls[0][0]).toBe(
      "ShadingMaterial: normalMap needs a per-fragment normal (shading 'phong'); gouraud shading ignores it",
    );
    warn.mockRestore();
    expect(() => new ShadingMaterial({ normalScale: [1, 1] as never })).toThrow(
      new TypeError('ShadingMaterial.normalScale must be a THREE.Vector2, got 1,1'),
    );
    const c = m.clone();
    expect([c.normalMap, c.normalScale.toArray()]).toEqual([normalMap, [0.5, -2]]);
  });
});
