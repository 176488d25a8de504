// What the material-scene spec compares besides the active GLSL (which `playground/src/learn/compiledShader.ts`
// computes for the tests and for the playground's shader view alike).

/**
 * Three's program cache key (without its `customProgramCacheKey` suffix: `…, flag mask 1, flag mask 2,
 * renderer.outputColorSpace`) with the `useFog` bit (bit 1 of the second flag mask) cleared.
 */
export function withoutUseFog(cacheKey: string): string {
  const parts = cacheKey.split(',');
  const i = parts.length - 2;
  parts[i] = String(Number(parts[i]) & ~2);
  return parts.join(',');
}
