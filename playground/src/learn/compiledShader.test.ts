import fc from 'fast-check';
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { fragmentShader, vertexShader } from '../../../packages/material/src/ShadingMaterial.glsl';
import {
  activeGlsl,
  activeSource,
  activeTags,
  isConditional,
  preprocess,
  tagForActive,
} from './compiledShader';

/** three's `#include <chunk>` expansion (WebGLProgram's resolveIncludes), recursively. */
function resolveIncludes(source: string): string {
  return source.replace(/^[ \t]*#include +<([\w\d./]+)>/gm, (_, name: string) =>
    resolveIncludes((THREE.ShaderChunk as Record<string, string>)[name]!),
  );
}

/** What the GPU gets from three for a material source: a prefix of #defines, then the source with its chunks. */
const compile = (prefix: string[], source: string) =>
  `#version 300 es\n${prefix.map((d) => `#define ${d}`).join('\n')}\n${resolveIncludes(source)}`;

describe('activeGlsl', () => {
  it('keeps the taken branches, normalised, and drops comments and conditionals', () => {
    const source = [
      '#define A 2',
      '#if A > 1 && !defined(B) // yes',
      '  float  x=1.0; /* kept */',
      '#elif defined(A)',
      '  float y;',
      '#else',
      '  float z;',
      '#endif',
      '#ifdef B',
      '  no;',
      '#endif',
    ].join('\n');
    expect(activeGlsl(source)).toBe('#define A 2\nfloat x = 1.0 ;');
  });

  it('names what it cannot evaluate and refuses unbalanced blocks', () => {
    expect(() => activeGlsl('#if vec3(1)\n#endif')).toThrow(/cannot evaluate #if vec3\(1\)/);
    expect(() => activeGlsl('#ifdef A\n')).toThrow(/unbalanced/);
    expect(() => activeGlsl('#endif\n')).toThrow(/#endif without #if/);
  });

  it('evaluates integer arithmetic, comparisons and logic as the C preprocessor does', () => {
    const on = (expression: string) => preprocess([`#if ${expression}`, 'x', '#endif'])[1]!.active;
    expect(on('1 + 2 * 3 == 7')).toBe(true);
    expect(on('(1 + 2) * 3 == 7')).toBe(false);
    expect(on('10 % 4 == 2 && 2u > 1')).toBe(true);
    expect(on('!0 || 0')).toBe(true);
    expect(on('N >= 1')).toBe(false); // an undefined name is 0
    expect(preprocess(['#if N >= 1', 'x', '#endif'], new Map([['N', '3']]))[1]!.active).toBe(true);
  });
});

describe('activeSource: the material source with only what is compiled', () => {
  const DEFINES = [
    'SHADING_PHONG',
    'SHADING_GOURAUD',
    'SHADING_FLAT',
    'FLAT_DERIVATIVES',
    'FLAT_CORNERS',
    'LIGHTING_BLINN',
    'USE_ATTENUATION',
    'SPHERE_NORMALS',
    'USE_INSTANCING',
    'USE_FOG',
    'DOUBLE_SIDED',
    'USE_LOGARITHMIC_DEPTH_BUFFER',
    'SHADING_EMISSIVE',
  ];

  it('compiles to the same active program as the full source, for any set of defines', () => {
    fc.assert(
      fc.property(
        fc.subarray(DEFINES),
        fc.integer({ min: 0, max: 4 }),
        fc.integer({ min: 1, max: 3 }),
        (defines, bands, lights) => {
          const prefix = [...defines, `CEL_BANDS ${bands}`, `NUM_LIGHTS ${lights}`];
          for (const source of [vertexShader, fragmentShader]) {
            const active = activeTags(compile(prefix, tagForActive(source)));
            const shown = activeSource(source, active);
            expect(activeGlsl(compile(prefix, shown))).toBe(activeGlsl(compile(prefix, source)));
            expect(shown.split('\n').some(isConditional)).toBe(false);
            expect(shown.length).toBeLessThan(source.length);
          }
        },
      ),
      { numRuns: 40 },
    );
  });

  it('drops the scene-feature plumbing of the lecture sphere and keeps the comments of the lines it keeps', () => {
    const prefix = ['SHADING_PHONG', 'LIGHTING_BLINN', 'CEL_BANDS 0', 'NUM_LIGHTS 1'];
    const shown = activeSource(fragmentShader, activeTags(compile(prefix, tagForActive(fragmentShader))));
    expect(fragmentShader).toContain('USE_INSTANCING');
    expect(shown).not.toContain('USE_INSTANCING');
    expect(shown).not.toMatch(/\n\s*\n\s*\n/); // blank runs kept as one line
    expect(shown).toContain('void main()');
    expect(shown).toContain('#include <logdepthbuf_pars_fragment>');
  });

  it('tags code and #define lines, not #pragma lines, loop ends or continued lines', () => {
    const tagged = tagForActive(
      [
        '#define A 1',
        '#pragma unroll_loop_start',
        'for (;;) {',
        '}',
        '#pragma unroll_loop_end',
        '#define B \\',
        ' 2',
      ].join('\n'),
    ).split('\n');
    expect(tagged).toEqual([
      '#define A 1 // @A1',
      '#pragma unroll_loop_start',
      'for (;;) { // @A3',
      '}',
      '#pragma unroll_loop_end',
      '#define B \\',
      ' 2 // @A7',
    ]);
  });
});
