/** How far a screenshot from another rasteriser (a real GPU) may be from a baseline. */
export interface GpuTolerance {
  /**
   * Codes (0 … 255) a pixel may lie outside the range its neighbourhood spans in the other picture, per
   * channel (see `compareNeighbourhood`).
   */
  readonly maxChannelDiff: number;
  /** Neighbourhood radius in pixels (an integer 0 … 8): edges may move this far. */
  readonly radiusPx: number;
  /** Pixels allowed beyond `maxChannelDiff`. */
  readonly maxDiffPixels: number;
}

/**
 * The default tolerance of `toMatchScreenshotAcrossGpus`, for smooth shading (Gouraud, Phong, ray-cast
 * impostors, three's own lit materials): the largest variation measured between rasterisers drawing the same
 * scene with the same settings (`bench/rasterisers.bench.mjs` → `bench/results/rasterisers.json`, `tolerance.smooth`;
 * BENCHMARKS.md, "Rasteriser variation"): a picture shifted by 1/16 pixel, the coarsest sub-pixel grid OpenGL ES
 * allows, and three's WebGPU and WebGL2 backends. Edges may move one pixel; no pixel may go beyond.
 */
export const GPU_TOLERANCE: GpuTolerance = { maxChannelDiff: 4, radiusPx: 1, maxDiffPixels: 0 };

/**
 * The tolerance for pictures with hard edges inside them (flat-shaded facets, cel bands), measured as
 * {@link GPU_TOLERANCE} is (`tolerance.hardEdges` in the same results): a 1-pixel sliver of a band or facet can
 * appear or vanish when the picture moves by a fraction of a pixel.
 */
export const GPU_TOLERANCE_HARD_EDGES: GpuTolerance = { maxChannelDiff: 18, radiusPx: 1, maxDiffPixels: 0 };

/**
 * The default tolerance of `toMatchAcrossRenderers`: the largest variation measured between three's renderers
 * drawing one scene with three's own material (`MeshPhongMaterial` on `WebGLRenderer`, converted to its node
 * material on `WebGPURenderer`'s WebGPU and WebGL2 backends), in one browser, on SwiftShader and on llvmpipe
 * (where WebGL is llvmpipe and WebGPU SwiftShader's adapter): `bench/rasterisers.bench.mjs` →
 * `tolerance.renderers`; BENCHMARKS.md, "Rasteriser variation". On one rasteriser the pictures differ by
 * 1 code on 620 of 76,800 pixels; across rasterisers edges also move by a pixel. So: each pixel within 1 code
 * of its 3 × 3 neighbourhood's range. A material that draws the same picture on every renderer stays within it; one whose colour differs by
 * 2 codes or more does not. When the pictures come from different rasterisers (llvmpipe's WebGL beside
 * SwiftShader's WebGPU adapter) or from a GPU, whose WebGL and WebGPU drivers differ, the matcher takes
 * {@link GPU_TOLERANCE} instead.
 */
export const RENDERER_TOLERANCE: GpuTolerance = { maxChannelDiff: 1, radiusPx: 1, maxDiffPixels: 0 };
