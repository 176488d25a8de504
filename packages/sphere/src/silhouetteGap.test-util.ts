// The true silhouette error of a sphere mesh in the image (the auditor's exact-outline gap method): one
// implementation, in bench/lib so that bench/autodetail.bench.mjs (plain Node) measures the same way.
export {
  exactOutline,
  type GapScene,
  silhouetteGapPx,
  sphereMesh,
} from '../../../bench/lib/silhouetteGap.mjs';
