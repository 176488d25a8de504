import { readFileSync } from 'node:fs';
import { estimateSphereBytes, SPHERE_BASES, sphereCounts } from '@shadelab/sphere';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';

/** Every module `file` imports, transitively (relative imports followed, bare ones collected). */
function importGraph(file: string, seen = new Set<string>(), bare = new Set<string>()) {
  if (seen.has(file)) return { seen, bare };
  seen.add(file);
  const source = readFileSync(new URL(file, import.meta.url), 'utf8');
  for (const [, specifier] of source.matchAll(/(?:import|export)[^'"]*from\s*'([^']+)'/g)) {
    if (specifier.startsWith('./')) importGraph(specifier.replace(/\.js$/, '.ts'), seen, bare);
    else bare.add(specifier);
  }
  return { seen, bare };
}

describe('sphereCounts and estimateSphereBytes', () => {
  it('counts satisfy Euler: V − E + T = 2, E = 3T/2, T = F0·4^level', () => {
    fc.assert(
      fc.property(fc.constantFrom(...SPHERE_BASES), fc.integer({ min: 0, max: 20 }), (base, level) => {
        const { triangles, vertices, edges } = sphereCounts(base, level);
        expect(vertices - edges + triangles).toBe(2);
        expect(2 * edges).toBe(3 * triangles);
        expect(triangles).toBe({ tetrahedron: 4, octahedron: 8, icosahedron: 20 }[base] * 4 ** level);
      }),
    );
  });

  it('the estimate grows 4× per level (3.2× where the indices switch to Uint32 and absorb the scratch) and never depends on the radius', () => {
    for (const base of SPHERE_BASES) {
      for (let level = 2; level <= 12; level++) {
        const r = estimateSphereBytes({ base, level }) / estimateSphereBytes({ base, level: level - 1 });
        // Smooth indexed: Uint16 levels take 12V + 18T + 12V ≈ 30T bytes, Uint32 levels 12V + 12T + 12V ≈ 24T.
        const switches =
          sphereCounts(base, level - 1).vertices <= 65536 && sphereCounts(base, level).vertices > 65536;
        expect(r).toBeGreaterThan(switches ? 3.15 : level <= 4 ? 3.7 : 3.99); // + 2 vertices weigh at small levels
        expect(r).toBeLessThan(switches ? 3.25 : 4.01);
        expect(estimateSphereBytes({ base, level, radius: 1e20 })).toBe(estimateSphereBytes({ base, level }));
      }
    }
  });

  it('validates like subdivideSphere', () => {
    expect(() => sphereCounts('cube' as never, 1)).toThrow(RangeError);
    expect(() => sphereCounts('icosahedron', -1)).toThrow(
      'sphereCounts: level must be an integer ≥ 0; got -1',
    );
    expect(() => estimateSphereBytes({ level: Number.NaN })).toThrow(RangeError);
    expect(() => estimateSphereBytes({ normals: 'flat', indexed: true })).toThrow(RangeError);
  });

  it('subdivideSphere and everything it imports never import three.js', () => {
    const { seen, bare } = importGraph('./subdivideSphere.ts');
    expect(seen.size).toBeGreaterThan(3);
    expect([...bare]).toEqual([]);
    // … and the same for the other three-free entry points; only the geometry class imports three.
    for (const file of ['./sphereError.ts', './chooseSphereDetail.ts', './computeVertexNormals.ts']) {
      expect([...importGraph(file).bare]).toEqual([]);
    }
    expect([...importGraph('./SubdivisionSphereGeometry.ts').bare]).toEqual(['three']);
  });
});
