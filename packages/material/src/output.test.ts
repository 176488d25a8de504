// The `output` and `normalMatrix` options of both materials: defaults, validation, live accessors, the defines
// (only when not the default) and the rebuilds, copy(). What they draw is tested in tests/material-output.spec.ts.
import {
  NORMAL_MATRIX_MODES,
  SHADING_OUTPUTS,
  ShadingMaterial,
  type ShadingOutput,
} from '@shadelab/material';
import { ShadingNodeMaterial } from '@shadelab/material/webgpu';
import { Group, IcosahedronGeometry, Mesh, PerspectiveCamera, Scene, type WebGLRenderer } from 'three';
import { describe, expect, it } from 'vitest';

/** What three does before a draw: onBeforeRender (which settles the defines). */
function draw(material: ShadingMaterial): void {
  const mesh = new Mesh(new IcosahedronGeometry(1, 1), material);
  const camera = new PerspectiveCamera();
  mesh.updateMatrixWorld();
  camera.updateMatrixWorld();
  material.onBeforeRender({} as WebGLRenderer, new Scene(), camera, mesh.geometry, mesh, new Group());
}

/** The defines of the output and normal-matrix options. */
function optionDefines(material: ShadingMaterial): string[] {
  return Object.keys(material.defines).filter(
    (k) => k.startsWith('SHADING_OUTPUT') || k.startsWith('SHADING_NO_') || k === 'SHADING_MODEL_NORMALS',
  );
}

describe.each([
  ['ShadingMaterial', (o?: object) => new ShadingMaterial(o)],
  ['ShadingNodeMaterial', (o?: object) => new ShadingNodeMaterial(o)],
] as const)('%s output and normalMatrix options', (owner, make) => {
  it("default to 'color' and 'inverse-transpose'", () => {
    const m = make();
    expect(m.output).toBe('color');
    expect(m.normalMatrix).toBe('inverse-transpose');
    expect(SHADING_OUTPUTS).toEqual(['color', 'ambient', 'diffuse', 'specular', 'attenuation', 'normal']);
    expect(NORMAL_MATRIX_MODES).toEqual(['inverse-transpose', 'model']);
  });

  it('take every value as an option and as a live property', () => {
    for (const output of SHADING_OUTPUTS) {
      expect(make({ output }).output).toBe(output);
      const m = make();
      m.output = output;
      expect(m.output).toBe(output);
    }
    for (const normalMatrix of NORMAL_MATRIX_MODES) {
      expect(make({ normalMatrix }).normalMatrix).toBe(normalMatrix);
      const m = make();
      m.normalMatrix = normalMatrix;
      expect(m.normalMatrix).toBe(normalMatrix);
    }
  });

  it('refuse other values with an error naming the parameter, the value and the allowed values', () => {
    expect(() => make({ output: 'colour' })).toThrow(
      new RangeError(
        `${owner}.output must be one of 'color', 'ambient', 'diffuse', 'specular', 'attenuation', 'normal', got "colour"`,
      ),
    );
    expect(() => make({ normalMatrix: 'inverse' })).toThrow(
      new RangeError(`${owner}.normalMatrix must be one of 'inverse-transpose', 'model', got "inverse"`),
    );
    expect(() => make({ output: 3 })).toThrow(TypeError);
    expect(() => make({ normalMatrix: null })).toThrow(TypeError);
    const m = make({ output: 'diffuse', normalMatrix: 'model' });
    expect(() => {
      m.output = 'Diffuse' as ShadingOutput;
    }).toThrow(RangeError);
    expect(() => {
      m.normalMatrix = '' as 'model';
    }).toThrow(RangeError);
    // A refused value leaves the property as it was.
    expect(m.output).toBe('diffuse');
    expect(m.normalMatrix).toBe('model');
  });

  it('copy() and clone() carry both', () => {
    const source = make({ output: 'specular', normalMatrix: 'model' });
    const target = make();
    // biome-ignore lint/suspicious/noExplicitAny: both classes' copy() take their own class.
    (target as any).copy(source);
    expect([target.output, target.normalMatrix]).toEqual(['specular', 'model']);
    const clone = source.clone();
    expect([clone.output, clone.normalMatrix]).toEqual(['specular', 'model']);
  });
});

describe('ShadingMaterial output and normalMatrix defines', () => {
  it('the default program has neither define; each other value has exactly its own', () => {
    const m = new ShadingMaterial();
    draw(m);
    const colour = { ...m.defines };
    expect(optionDefines(m)).toEqual([]);
    for (const output of SHADING_OUTPUTS.filter((o) => o !== 'color')) {
      m.output = output;
      const own = `SHADING_OUTPUT_${output.toUpperCase()}`;
      expect(optionDefines(m)).toContain(own);
      expect(optionDefines(m).filter((k) => k.startsWith('SHADING_OUTPUT_') && k !== own)).toEqual(
        output === 'attenuation' || output === 'normal'
          ? ['SHADING_OUTPUT_TERM', 'SHADING_OUTPUT_DATA']
          : ['SHADING_OUTPUT_TERM'],
      );
    }
    m.output = 'color';
    expect(m.defines).toEqual(colour);
    m.normalMatrix = 'model';
    expect(optionDefines(m)).toEqual(['SHADING_MODEL_NORMALS']);
    m.normalMatrix = 'inverse-transpose';
    expect(m.defines).toEqual(colour);
  });

  it('recompiles when a value changes, not when the same value is set again', () => {
    const m = new ShadingMaterial();
    draw(m);
    let version = m.version;
    m.output = 'color';
    m.normalMatrix = 'inverse-transpose';
    expect(m.version).toBe(version);
    m.output = 'normal';
    expect(m.version).toBeGreaterThan(version);
    version = m.version;
    m.output = 'normal';
    draw(m);
    expect(m.version).toBe(version);
    m.normalMatrix = 'model';
    expect(m.version).toBeGreaterThan(version);
  });

  it('copy() carries the defines', () => {
    const source = new ShadingMaterial({ output: 'attenuation', normalMatrix: 'model' });
    const target = new ShadingMaterial().copy(source);
    draw(target);
    expect(optionDefines(target)).toEqual([
      'SHADING_OUTPUT_ATTENUATION',
      'SHADING_OUTPUT_TERM',
      'SHADING_OUTPUT_DATA',
      'SHADING_NO_AMBIENT',
      'SHADING_MODEL_NORMALS',
    ]);
  });
});

describe('ShadingNodeMaterial output and normalMatrix rebuilds', () => {
  it('a changed value rebuilds the material, the same value does not', () => {
    const m = new ShadingNodeMaterial();
    let version = m.version;
    m.output = 'color';
    m.normalMatrix = 'inverse-transpose';
    expect(m.version).toBe(version);
    m.output = 'ambient';
    expect(m.version).toBeGreaterThan(version);
    version = m.version;
    m.normalMatrix = 'model';
    expect(m.version).toBeGreaterThan(version);
  });
});
