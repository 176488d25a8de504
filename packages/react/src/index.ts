/**
 * React Three Fiber for shadelab: importing the package registers every shadelab class as a typed JSX element
 * (`<shadingMaterial>`, `<phongLight>`, `<subdivisionSphereGeometry>`, `<outlineMaterial>`,
 * `<sphereImpostorMaterial>`, `<sphereImpostor>`, `<autoDetailSphere>`), and it gives the components
 * `<Trackball>` (with the `useTrackball` hook), `<LectureCamera>`, `<AutoDetailSphere>` and `<ShadedModel>`
 * (with the `useSwapMaterials` hook: a loaded model's materials swapped for ShadingMaterials), and
 * `<Adaptive maxError>` (with the `useAdaptiveShading` hook: the cheapest shading and detail under an error budget,
 * every frame).
 * @module @shadelab/react
 * @mergeModuleWith <project>
 */
// The registration of the JSX elements (the package's side effect; see package.json `sideEffects`).
import './elements.js';

export type { ColorInput } from '@shadelab/material';
export { Adaptive, type AdaptiveProps } from './Adaptive.js';
export { AutoDetailSphere, type AutoDetailSphereProps } from './AutoDetailSphere.js';
export type { ColorProp, ShadelabElement, ShadelabElements } from './elements.js';
export { LectureCamera, type LectureCameraProps } from './LectureCamera.js';
export { ShadedModel, type ShadedModelProps } from './ShadedModel.js';
export { Trackball, type TrackballEvent, type TrackballProps } from './Trackball.js';
export { useAdaptiveShading } from './useAdaptiveShading.js';
export { useSwapMaterials } from './useSwapMaterials.js';
export { type UseTrackballOptions, useTrackball } from './useTrackball.js';
