// Vitest setup file (vitest.config.ts and tools/three-compat/vitest.config.ts): every fast-check property in
// `npm test` runs from one fixed seed, so the gate gives the same result on every run and every machine.
// Exploring with fresh seeds is `npm run fuzz` (scripts/fuzz.mjs), which sets SHADELAB_FUZZ_SEED for each run.
import fc from 'fast-check';

/** The seed of every fast-check property in `npm test` unless SHADELAB_FUZZ_SEED sets another. */
export const DEFAULT_FUZZ_SEED = 13;

/**
 * The seed from `SHADELAB_FUZZ_SEED` (an integer from -2^31 to 2^31 − 1), or {@link DEFAULT_FUZZ_SEED} when the
 * variable is unset or empty.
 * @throws RangeError naming the variable when it is set to anything else.
 */
export function fuzzSeedFromEnvironment(value = process.env.SHADELAB_FUZZ_SEED): number {
  if (value === undefined || value.trim() === '') return DEFAULT_FUZZ_SEED;
  const seed = Number(value);
  if (!/^\s*-?\d+\s*$/.test(value) || !Number.isSafeInteger(seed) || seed < -(2 ** 31) || seed >= 2 ** 31) {
    throw new RangeError(
      `SHADELAB_FUZZ_SEED must be an integer from -2147483648 to 2147483647, got ${JSON.stringify(value)}`,
    );
  }
  return seed;
}

// includeErrorInReport: the failure message itself says what went wrong (`Got error: …`), so the JSON report that
// scripts/fuzz.mjs reads has it (by default it is only the error's cause).
fc.configureGlobal({
  ...fc.readConfigureGlobal(),
  seed: fuzzSeedFromEnvironment(),
  includeErrorInReport: true,
});
