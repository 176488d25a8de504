// Type-checked by the pack test (tsc --noEmit, strict, skipLibCheck off), not bundled: the subpath entries
// resolve with their declarations from the tarballs, under moduleResolution "bundler".
import type { SphereImpostorMaterialOptions } from '@shadelab/material/impostor';
import type { OutlineMaterialOptions } from '@shadelab/material/outline';
import { chooseSphereDetail, type SphereDetail } from '@shadelab/sphere/detail';

export const impostorOptions: SphereImpostorMaterialOptions = { lighting: 'blinn-phong', celBands: 3 };
export const detail: SphereDetail = chooseSphereDetail({ radiusPx: 200, maxErrorPx: 0.5 });
export const outlineOptions: OutlineMaterialOptions = { thickness: 0.05, color: '#000000' };
