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
