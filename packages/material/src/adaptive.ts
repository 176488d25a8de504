/**
 * Adaptive shading under an error budget: `AdaptiveShading` picks, every frame, the cheapest shading (and a
 * subdivision sphere's level) per object and per group of instances that keeps the image within `maxError`
 * 8-bit sRGB levels of Phong shading at full detail; `measureShadingError`, the measured error model it uses;
 * `shadingCost` and `chooseFlatPath`, the measured costs; `pictureError`, the error its budget bounds, measured on
 * two pictures.
 * @module @shadelab/material/adaptive
 */
export {
  type AdaptiveAddOptions,
  type AdaptiveChoice,
  AdaptiveShading,
  type AdaptiveShadingOptions,
  type AdaptiveUpdateStats,
} from './AdaptiveShading.js';
export {
  type CostedShading,
  chooseFlatPath,
  type FlatPath,
  SHADING_COST_TABLE,
  shadingCost,
} from './adaptiveCosts.js';
export { type AllocationUnit, allocateShading } from './allocateShading.js';
export { type PictureError, pictureError } from './pictureError.js';
export {
  ERROR_BUDGETS,
  fibonacciDirections,
  measureShadingError,
  overFraction,
  type ShadingErrorLevel,
  type ShadingErrorModelOptions,
  type ShadingErrorRow,
  type ShadingErrorSurface,
  type ShadingErrorTable,
} from './shadingErrorModel.js';
