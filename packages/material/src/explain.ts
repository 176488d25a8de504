/**
 * The lecture's equation at one point, kept apart term by term (`explainShade`): what a pixel probe, a lesson or
 * a test shows of `shade()`'s sum. Opt-in: an app that only draws does not ship it.
 * @module @shadelab/material/explain
 */
export { explainShade, type LightExplanation, type ShadeExplanation } from './explainShade.js';
