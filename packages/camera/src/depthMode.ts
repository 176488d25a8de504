import type { WebGLRenderer } from 'three';

/**
 * How depth is stored (a renderer-wide choice, fixed when the `WebGLRenderer` is created):
 * - `'standard'`: NDC z in [−1, 1] into the 24-bit fixed-point default depth buffer. Precision follows
 *   Δz/z ≈ 2⁻²³ · z / near: it is spent near the near plane, so surfaces far from the camera merge.
 * - `'logarithmic'`: the fragment shader writes `log2(1 + w) / log2(1 + far)` (three's
 *   `logarithmicDepthBuffer`): Δz/z ≈ 2⁻²⁴ · ln 2 · log2(1 + far) · (1 + z)/z, almost the same everywhere,
 *   for perspective cameras. Costs a `gl_FragDepth` write (no early depth test) in every material.
 * - `'reversed'`: reversed-Z (three's `reversedDepthBuffer`, needs `EXT_clip_control`): near → 1, far → 0,
 *   clip z in [0, 1]. With a floating-point depth buffer (a render target whose `depthTexture.type` is
 *   `FloatType`) Δz/z ≈ 2⁻²⁴ at every distance and far/near; into the 24-bit default buffer it only removes the
 *   [−1, 1] → [0, 1] rounding and behaves like `'standard'`.
 */
export type DepthMode = 'standard' | 'logarithmic' | 'reversed';

/**
 * What to ask a renderer for: a {@link DepthMode}, or `'reversed-or-logarithmic'`: reversed-Z where
 * `EXT_clip_control` exists, logarithmic depth where it does not (both of three's switches on; three keeps
 * reversed-Z when it can, with a console warning that the logarithmic switch is ignored, and falls back to
 * logarithmic otherwise). Plain `'reversed'` is three's `reversedDepthBuffer` alone, which falls back to
 * `'standard'`, the least precise mode.
 */
export type DepthModeRequest = DepthMode | 'reversed-or-logarithmic';

const MODES: readonly string[] = ['standard', 'logarithmic', 'reversed', 'reversed-or-logarithmic'];

/** The `WebGLRenderer` constructor parameters that select a {@link DepthMode}. */
export interface DepthBufferParameters {
  /** three's logarithmic depth buffer switch. */
  logarithmicDepthBuffer: boolean;
  /** three's reversed depth buffer switch (ignored with a warning when `EXT_clip_control` is missing). */
  reversedDepthBuffer: boolean;
}

/**
 * Renderer parameters for a depth mode:
 * `new WebGLRenderer({ canvas, ...depthBufferParameters('reversed-or-logarithmic') })`.
 * @param mode - The depth mode to ask for; {@link depthModeOf} tells what the renderer then runs.
 * @throws RangeError for an unknown mode.
 */
export function depthBufferParameters(mode: DepthModeRequest): DepthBufferParameters {
  if (!MODES.includes(mode))
    throw new RangeError(`mode must be one of ${MODES.join(', ')}, got ${String(mode)}`);
  return {
    logarithmicDepthBuffer: mode.endsWith('logarithmic'),
    reversedDepthBuffer: mode.startsWith('reversed'),
  };
}

/**
 * The depth mode a renderer actually uses: without `EXT_clip_control` a `'reversed'` request falls back to
 * `'standard'` and a `'reversed-or-logarithmic'` one to `'logarithmic'`.
 */
export function depthModeOf(renderer: Pick<WebGLRenderer, 'capabilities'>): DepthMode {
  const { capabilities } = renderer;
  if ((capabilities as { reversedDepthBuffer?: boolean }).reversedDepthBuffer) return 'reversed';
  if (capabilities.logarithmicDepthBuffer) return 'logarithmic';
  return 'standard';
}
