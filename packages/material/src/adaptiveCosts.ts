// The measured cost of each shading, relative to Phong shading of the same mesh, as a function of how many
// triangles the mesh has per covered pixel. The numbers are derived from the committed bench JSON
// (bench/results/tradeoff.json and scene.json); adaptiveCosts.test.ts recomputes them from there and fails
// when they drift apart.

/** The path flat shading takes: a prepared `flatShadingGeometry`, or per-fragment screen-space derivatives. */
export type FlatPath = 'prepared' | 'derivatives';

/** What `shadingCost` prices: the three shadings, flat shading by either path. */
export type CostedShading = 'phong' | 'gouraud' | 'flat-prepared' | 'flat-derivatives';

/**
 * Measured frame cost of each shading relative to Phong shading of the same mesh at the same size on screen,
 * by triangles per covered pixel τ (rows: log10 τ). Flat and Gouraud: the medians, per half-decade of τ, of the
 * GPU-timer ratios in `bench/results/tradeoff.json` (one sphere, every base at levels 0 … 8, ~160,000 pixels,
 * 1280×720, headless Chromium on SwiftShader); flat shading there draws a `flatShadingGeometry`. Flat by
 * derivatives: the prepared ratio times the derivatives/prepared ratio of `bench/results/scene.json`'s flat
 * meshes (2.39× at τ = 0.0009, 2.46× at 0.0031, 1.54× at 0.09), interpolated in log τ and carried past the last
 * point with the last segment's slope, never below 0.5 (the prepared geometry at most doubles the vertices).
 * The order is not flat < Gouraud < Phong: above about 0.5 triangles per pixel flat (prepared) costs more
 * than Phong, and above about 3 Gouraud does too (vertices cost more than pixels there).
 */
export const SHADING_COST_TABLE = Object.freeze({
  /** The rows: log10 of triangles per covered pixel. */
  log10TrianglesPerPixel: Object.freeze([-4, -3.5, -3, -2.5, -2, -1.5, -1, -0.5, 0, 0.5, 1]),
  /** Flat shading of a `flatShadingGeometry` / Phong shading, per row. */
  flat: Object.freeze([0.55, 0.44, 0.45, 0.53, 0.48, 0.53, 0.71, 0.94, 1.11, 1.44, 1.83]),
  /** Gouraud shading / Phong shading, per row. */
  gouraud: Object.freeze([0.52, 0.52, 0.51, 0.53, 0.57, 0.55, 0.69, 0.92, 0.97, 1.19, 1.51]),
  /** `bench/results/scene.json` flat meshes: [log10 τ, derivatives / prepared] (τ = triangles / face pixels). */
  derivativesOverPrepared: Object.freeze([
    Object.freeze([-3.0438, 2.39]),
    Object.freeze([-2.5146, 2.46]),
    Object.freeze([-1.0432, 1.54]),
  ]),
  /**
   * One triangle's cost in pixels of Phong shading: the least-squares slope of Phong frame time against
   * triangles (τ ≥ 0.1) over the median Phong time per pixel (τ ≤ 0.01), both from tradeoff.json.
   */
  pixelsPerTriangle: 5.3,
});

/** Piecewise-linear interpolation of `ys` over ascending `xs`, clamped to the ends. */
function interpolate(xs: readonly number[], ys: readonly number[], x: number): number {
  if (!(x > xs[0])) return ys[0];
  const n = xs.length - 1;
  if (x >= xs[n]) return ys[n];
  let i = 0;
  while (xs[i + 1] < x) i++;
  const t = (x - xs[i]) / (xs[i + 1] - xs[i]);
  return ys[i] + t * (ys[i + 1] - ys[i]);
}

/** log10 τ, clamped to the table's range (0 pixels: the vertex-bound end). */
function logTau(triangles: number, pixels: number): number {
  const xs = SHADING_COST_TABLE.log10TrianglesPerPixel;
  if (!(pixels > 0)) return xs[xs.length - 1];
  const l = Math.log10(triangles / pixels);
  return Number.isFinite(l) ? l : l > 0 ? xs[xs.length - 1] : xs[0];
}

/** derivatives / prepared at log10 τ = `x` (see {@link SHADING_COST_TABLE}). */
function derivativesFactor(x: number): number {
  const d = SHADING_COST_TABLE.derivativesOverPrepared;
  const xs = d.map((p) => p[0]);
  const ys = d.map((p) => p[1]);
  const n = d.length - 1;
  if (x <= xs[n]) return interpolate(xs, ys, x);
  const slope = (ys[n] - ys[n - 1]) / (xs[n] - xs[n - 1]);
  return Math.max(0.5, ys[n] + slope * (x - xs[n]));
}

/**
 * The cost of drawing a mesh of `triangles` triangles covering `pixels` pixels with `shading`, in pixels of
 * Phong shading: (pixels + 5.3 · triangles) × the measured ratio of {@link SHADING_COST_TABLE} at τ =
 * triangles / pixels. Measured on SwiftShader (CPU rasterisation): on a GPU the ratios differ; the order of
 * the choices it gives is what `AdaptiveShading` uses.
 * @param shading - the shading (flat by its path).
 * @param triangles - triangles drawn, ≥ 0.
 * @param pixels - pixels covered, ≥ 0.
 */
export function shadingCost(shading: CostedShading, triangles: number, pixels: number): number {
  const area = Number.isFinite(pixels) && pixels > 0 ? pixels : 0;
  const phong = area + SHADING_COST_TABLE.pixelsPerTriangle * triangles;
  if (shading === 'phong') return phong;
  const x = logTau(triangles, area);
  const xs = SHADING_COST_TABLE.log10TrianglesPerPixel;
  if (shading === 'gouraud') return phong * interpolate(xs, SHADING_COST_TABLE.gouraud, x);
  const flat = phong * interpolate(xs, SHADING_COST_TABLE.flat, x);
  return shading === 'flat-prepared' ? flat : flat * derivativesFactor(x);
}

/**
 * Flat shading's cheaper path for a mesh of `triangles` triangles covering `pixels` pixels, by the measured
 * costs ({@link SHADING_COST_TABLE}): the prepared `flatShadingGeometry` below about 0.66 triangles per pixel
 * (it lights each face once per vertex but about doubles the vertices of a closed mesh), screen-space
 * derivatives above (per-fragment lighting on the original, indexed vertices).
 */
export function chooseFlatPath(triangles: number, pixels: number): FlatPath {
  return derivativesFactor(logTau(triangles, pixels)) < 1 ? 'derivatives' : 'prepared';
}
