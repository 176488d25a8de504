/** How far a screenshot from another rasteriser (a real GPU) may be from a baseline. */
export interface GpuTolerance {
  /**
   * Codes (0 … 255) a pixel may lie outside the range its neighbourhood spans in the other picture, per
   * channel (see `compareNeighbourhood`).
   */
  readonly maxChannelDiff: number;
  /** Neighbourhood radius in pixels: edges may move this far. */
  readonly radiusPx: number;
  /** Pixels allowed beyond `maxChannelDiff`. */
  readonly maxDiffPixels: number;
}

/**
 * The default tolerance of `toMatchScreenshotAcrossGpus`, derived from the largest variation measured between
 * rasterisers drawing the same scenes (`bench/rasterisers.bench.mjs` → `bench/results/rasterisers.json`;
 * BENCHMARKS.md, "Rasteriser variation"): `maxChannelDiff` is the largest neighbourhood excess measured there,
 * edges may move one pixel, and no pixel may go beyond.
 */
export const GPU_TOLERANCE: GpuTolerance = { maxChannelDiff: 3, radiusPx: 1, maxDiffPixels: 0 };
