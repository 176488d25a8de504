// Copy as code, the generators alone: minimal (an option at its package default writes no line), complete (every
// state field is either in the code, and changing it changes both programs, or documented as not exported), and
// numbers written to 15 significant digits (num() itself, and the install line: copyCodeFormat.test.ts). The
// programs are pasted, type-checked, built and run against the playground's picture in
// tests/playground-copy-code.spec.ts.
import { describe, expect, test } from 'vitest';
import { isField, LIGHT_FIELDS, STATE_FIELDS, type Table } from '../state/fields';
import { defaultState, type PlaygroundState, SCENES, validateState } from '../state/schema';
import { NOT_EXPORTED, programOf } from './copyCode';
import { codeScene, defaults } from './copyCodeModel';

/** Every leaf field of the state, as a path (`material.ka`, `lights[].position`, `lights[].attenuation.a`). */
function leaves(table: Table, prefix = ''): string[] {
  return Object.entries(table).flatMap(([key, entry]) => {
    const path = `${prefix}${key}`;
    if (!isField(entry)) return leaves(entry, `${path}.`);
    if (entry.kind.type === 'list') return leaves(entry.kind.item, `${path}[].`);
    return [path];
  });
}

/** A state with the packages' defaults where the playground has its own (no option differs from a default). */
function packageDefaultState(): PlaygroundState {
  const s = defaultState();
  const d = defaults();
  Object.assign(s.material, {
    shading: d.material['shading'],
    lighting: d.material['lighting'],
    ka: d.material['ka'],
    kd: d.material['kd'],
    ks: d.material['ks'],
    shininess: d.material['shininess'],
  });
  s.model.scale = [1, 1, 1];
  return s;
}

/** Sets a path of the state (`lights[].x` sets the first light's). */
function set(state: PlaygroundState, path: string, value: unknown): void {
  const keys = path.replace('[]', '.0').split('.');
  let at = state as unknown as Record<string, unknown>;
  for (const key of keys.slice(0, -1)) at = at[key] as Record<string, unknown>;
  at[keys.at(-1)!] = value;
}
function get(state: PlaygroundState, path: string): unknown {
  return path
    .replace('[]', '.0')
    .split('.')
    .reduce((at, key) => (at as Record<string, unknown>)[key], state as unknown);
}

/** Another valid value of each exported field, and what must be on for the field to show in the code. */
const CHANGES: Record<string, { value: unknown; needs?: (s: PlaygroundState) => void }> = {
  scene: { value: 'instanced' },
  'material.shading': { value: 'gouraud' },
  'material.lighting': { value: 'phong' },
  'material.celBands': { value: 3 },
  'material.outline': {
    value: true,
    needs: (s) => {
      s.material.celBands = 3;
    },
  },
  'material.outlineWidth': {
    value: 0.07,
    needs: (s) => Object.assign(s.material, { celBands: 3, outline: true }),
  },
  'material.outlineColor': {
    value: '#123456',
    needs: (s) => Object.assign(s.material, { celBands: 3, outline: true }),
  },
  'material.ka': { value: [0.1, 0.2, 0.3] },
  'material.kd': { value: [0.3, 0.2, 0.1] },
  'material.ks': { value: [0.25, 0.5, 0.75] },
  'material.shininess': { value: 7 },
  'material.output': { value: 'diffuse' },
  'material.normalMatrix': { value: 'model' },
  'lights[].position': { value: [1, 2, 3] },
  'lights[].ambient': { value: [0.3, 0.3, 0.3] },
  'lights[].diffuse': { value: [0.5, 0.6, 0.7] },
  'lights[].specular': { value: [0.1, 0.1, 0.1] },
  'lights[].attenuation.a': { value: 2 },
  'lights[].attenuation.b': { value: 0.5 },
  'lights[].attenuation.c': { value: 0.25 },
  'sphere.render': { value: 'impostor' },
  'sphere.base': { value: 'icosahedron' },
  'sphere.level': { value: 4 },
  'sphere.auto': { value: true },
  'sphere.maxErrorPx': {
    value: 2,
    needs: (s) => {
      s.sphere.auto = true;
    },
  },
  'sphere.radius': { value: 1.5 },
  'model.scale': { value: [3, 1, 1] },
  'camera.projection': { value: 'orthographic' },
  'camera.depth': { value: 'logarithmic' },
  'camera.eye': { value: [0, 1, 4] },
  'camera.at': { value: [0, 0.5, 0] },
  'camera.up': { value: [1, 1, 0] },
  'camera.fovy': { value: 60 },
  'camera.near': { value: 0.5 },
  'camera.far': { value: 20 },
  'camera.right': {
    value: 3,
    needs: (s) => {
      s.camera.projection = 'orthographic';
    },
  },
  'camera.left': {
    value: -3,
    needs: (s) => {
      s.camera.projection = 'orthographic';
    },
  },
  'camera.top': {
    value: 2,
    needs: (s) => {
      s.camera.projection = 'orthographic';
    },
  },
  'camera.bottom': {
    value: -2,
    needs: (s) => {
      s.camera.projection = 'orthographic';
    },
  },
  'camera.fitAspect': {
    value: false,
    needs: (s) => {
      s.camera.projection = 'orthographic';
    },
  },
  'camera.zoom': {
    value: 2,
    needs: (s) => {
      s.camera.projection = 'orthographic';
    },
  },
  'trackball.mapping': { value: 'arcball' },
  'trackball.rotateSpeed': { value: 2 },
  'trackball.zoomSpeed': { value: 0.5 },
  'trackball.minZoom': { value: 0.1 },
  'trackball.maxZoom': { value: 10 },
  'trackball.radius': { value: 0.8 },
  'trackball.damping': { value: true },
  'trackball.dampingFactor': {
    value: 0.2,
    needs: (s) => {
      s.trackball.damping = true;
    },
  },
  'trackball.rotation': { value: [0, 0.6, 0, 0.8] },
};

describe('copy as code', () => {
  const fields = [...leaves(STATE_FIELDS)];

  test('every state field is in the code or documented as not exported, never both', () => {
    expect(leaves(LIGHT_FIELDS).length).toBeGreaterThan(0);
    for (const path of fields) {
      const exported = path in CHANGES;
      const documented = path in NOT_EXPORTED;
      expect(exported !== documented, `${path}: exported ${exported}, documented ${documented}`).toBe(true);
    }
    for (const path of Object.keys(NOT_EXPORTED)) expect(fields).toContain(path);
    for (const reason of Object.values(NOT_EXPORTED)) expect(reason.length).toBeGreaterThan(10);
  });

  for (const path of Object.keys(CHANGES)) {
    test(`${path}: a new value changes both programs and is written in them`, () => {
      const { value, needs } = CHANGES[path]!;
      const before = defaultState();
      needs?.(before);
      const after = structuredClone(before);
      set(after, path, value);
      expect(get(after, path)).not.toEqual(get(before, path));
      const checked = validateState(after);
      expect(checked.ok, checked.ok ? '' : checked.error).toBe(true);
      for (const variant of ['three', 'r3f'] as const) {
        expect(programOf(variant, after), variant).not.toBe(programOf(variant, before));
      }
      // A number or colour component is written as given (shortest round-trip form).
      if (typeof value === 'number' && path !== 'material.celBands') {
        expect(programOf('three', after)).toContain(String(value));
      }
    });
  }

  test('minimal: options at the packages’ defaults write no option, only the scene’s own lines', () => {
    const state = packageDefaultState();
    state.lights[0]!.position = [0, 0, 0];
    const code = codeScene(state);
    expect(code.material).toEqual({});
    expect(code.lights).toEqual([{ options: {}, position: null }]);
    expect(code.trackball).toEqual({});
    expect(code.outline).toBeNull();
    expect(code.scale).toBeNull();
    expect(code.rotation).toBeNull();
    expect(code.depth).toBeNull();
    const three = programOf('three', state);
    expect(three).toContain('new ShadingMaterial()');
    expect(three).toContain('new PhongLight()');
    expect(three).toContain("new SubdivisionSphereGeometry({ normals: 'none' })");
    expect(three).toContain('new Trackball(sphere, renderer.domElement, { camera })');
    expect(three).not.toMatch(/position\.set|scale\.set|quaternion|createOutline|depthBuffer|zoom/);
    const r3f = programOf('r3f', state);
    expect(r3f).toContain('<shadingMaterial />');
    expect(r3f).toContain('<phongLight />');
    expect(r3f).toContain('<Trackball>');
  });

  test("the playground's defaults: only what differs from the packages' defaults is written", () => {
    const three = programOf('three', defaultState());
    // The playground's material (the lecture never sets ka, kd, ks or α) and its Blinn-Phong lighting.
    expect(three).toContain(
      "new ShadingMaterial({ lighting: 'blinn-phong', ka: [0.8, 0.35, 0.15], kd: [0.8, 0.35, 0.15], ks: 1, shininess: 50 })",
    );
    // The lecture's light is PhongLight's default; only its position is written.
    expect(three).toContain('new PhongLight();');
    expect(three).toContain('light.position.set(-5, 10, 20);');
    expect(three).toContain('camera.setPerspective(90, innerWidth / innerHeight, 0.1, 10);');
    expect(three).toContain('sphere.scale.set(2, 1, 2);');
    // Package names, never the playground's modules.
    expect(three).not.toMatch(/from '\.|playground|engine|state\//);
    // The README's Install: the tarballs `npm run pack` writes (the packages are not on npm yet), three beside them.
    expect(three.split('\n').slice(0, 2)).toEqual([
      '// The @shadelab packages are not on npm yet: in a clone of shadelab, `npm ci && npm run pack -- --out /tmp/shadelab`, then',
      '// npm install three /tmp/shadelab/shadelab-{camera,material,sphere,trackball}-*.tgz && npm install --save-dev @types/three',
    ]);
    const r3f = programOf('r3f', defaultState());
    // The R3F app imports nothing from three itself; three is installed all the same (every package's peer).
    // @shadelab/react's own @shadelab peers come from the tarballs too (npm would look for them on the registry).
    expect(r3f.split('\n')[1]).toBe(
      '// npm install @react-three/fiber react react-dom three /tmp/shadelab/shadelab-{camera,material,react,sphere,trackball}-*.tgz && npm install --save-dev @types/react @types/react-dom @types/three',
    );
    expect(r3f).toContain('<LectureCamera makeDefault fovy={90} far={10} />');
    expect(r3f).toContain('ks={[1, 1, 1]}'); // a number would be a hex colour in an R3F prop
    expect(r3f).not.toMatch(/from '\.|playground|engine|state\//);
  });

  test('every scene, shading and drawing of the sphere gives both programs, the outline only with cel bands', () => {
    for (const scene of SCENES) {
      for (const shading of ['flat', 'gouraud', 'phong'] as const) {
        for (const [celBands, outline] of [
          [0, true],
          [3, false],
          [3, true],
        ] as const) {
          for (const render of ['mesh', 'impostor'] as const) {
            const state = defaultState();
            Object.assign(state.material, { shading, celBands, outline });
            Object.assign(state, { scene });
            state.sphere.render = render;
            const outlined = celBands > 0 && outline && !(scene === 'sphere' && render === 'impostor');
            for (const variant of ['three', 'r3f'] as const) {
              const code = programOf(variant, state);
              expect(/createOutline|outlineMaterial/.test(code), `${scene} ${shading} ${variant}`).toBe(
                outlined,
              );
              expect(code.includes('flatShadingGeometry') || code.includes('toNonIndexed'), scene).toBe(
                shading === 'flat' && scene !== 'model' && !(scene === 'sphere' && render === 'impostor'),
              );
            }
          }
        }
      }
    }
  });

  test('numbers are written to 15 significant digits, without the noise of arithmetic', () => {
    const state = defaultState();
    state.material.shininess = 0.1 + 0.2;
    state.trackball.rotation = [0, Math.SQRT1_2, 0, Math.SQRT1_2];
    state.camera.at = [0, 0, -0.20000000000000018];
    const three = programOf('three', state);
    expect(three).toContain('shininess: 0.3');
    expect(three).toContain('sphere.quaternion.set(0, 0.707106781186548, 0, 0.707106781186548);');
    expect(three).toContain('[0, 0, -0.2]');
  });

  test('a glTF model: GLTFLoader with a placeholder URL and swapMaterials with the shading options', () => {
    const state = defaultState();
    state.scene = 'model';
    state.material.celBands = 3;
    const three = programOf('three', state);
    expect(three).toContain("import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';");
    expect(three).toContain("new GLTFLoader().load('/model.glb', (gltf) => {");
    expect(three).toContain("swapMaterials(model, { lighting: 'blinn-phong', celBands: 3 });");
    // ka/kd/ks and α are the model's own.
    expect(three).not.toContain('ka:');
    const r3f = programOf('r3f', state);
    expect(r3f).toContain("useLoader(GLTFLoader, '/model.glb')");
    expect(r3f).toContain('<ShadedModel object={gltf.scene}');
  });
});
