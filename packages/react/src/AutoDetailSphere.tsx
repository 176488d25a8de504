import { type ThreeElements, useFrame, useThree } from '@react-three/fiber';
import { ShadingMaterial } from '@shadelab/material';
import {
  AutoDetailSphere as AutoDetailSphereMesh,
  type AutoDetailSphereOptions,
} from '@shadelab/sphere/detail';
import { type ReactNode, type Ref, useEffect, useImperativeHandle, useMemo } from 'react';
import type { Material } from 'three';

/** Props of {@link AutoDetailSphere}: the mesh's options, its material, and R3F's mesh props. */
export interface AutoDetailSphereProps
  extends AutoDetailSphereOptions,
    Omit<ThreeElements['mesh'], 'args' | 'geometry' | 'material' | 'ref' | 'children'> {
  /** The material. @default a `ShadingMaterial` with its defaults (lit by the scene's lights), or a material child */
  material?: Material;
  /** A material element (`<shadingMaterial … />`) attaches as the mesh's material. */
  children?: ReactNode;
  /** Receives the `AutoDetailSphere` mesh. */
  ref?: Ref<AutoDetailSphereMesh>;
}

/**
 * `AutoDetailSphere` (`@shadelab/sphere/detail`) that follows R3F's camera: before every frame it chooses the
 * cheapest sphere whose silhouette error on screen stays within `maxErrorPx` for the current camera and canvas,
 * so the frame is drawn with the right detail. Its options are constructor options: changing one makes a new
 * mesh. The geometries it built are disposed on unmount (the material too when it is the default one).
 *
 * @example
 * <AutoDetailSphere maxErrorPx={0.5} scale={[2, 1, 2]}>
 *   <shadingMaterial shading="phong" />
 * </AutoDetailSphere>
 */
export function AutoDetailSphere({
  maxErrorPx,
  bases,
  maxLevel,
  radius,
  normals,
  indexed,
  material,
  children,
  ref,
  ...meshProps
}: AutoDetailSphereProps) {
  const invalidate = useThree((state) => state.invalidate);
  const fallback = useMemo(() => (material ? null : new ShadingMaterial()), [material]);
  const basesKey = bases ? bases.join() : '';
  // biome-ignore lint/correctness/useExhaustiveDependencies: bases is keyed by its names; the material is set below.
  const sphere = useMemo(
    () =>
      new AutoDetailSphereMesh(material ?? (fallback as Material), {
        maxErrorPx,
        bases,
        maxLevel,
        radius,
        normals,
        indexed,
      }),
    [maxErrorPx, basesKey, maxLevel, radius, normals, indexed],
  );
  useImperativeHandle(ref, () => sphere, [sphere]);

  useEffect(() => {
    if (material) sphere.material = material;
  }, [sphere, material]);
  useEffect(() => () => fallback?.dispose(), [fallback]);
  useEffect(() => {
    // A change found in onBeforeRender (the camera moved without a frame of ours) shows from the next frame.
    const onChange = () => invalidate();
    sphere.addEventListener('change' as never, onChange);
    return () => {
      sphere.removeEventListener('change' as never, onChange);
      sphere.disposeGeometries();
    };
  }, [sphere, invalidate]);

  // Before R3F renders (priority below 0 leaves its render loop in place).
  useFrame(({ camera, gl }) => {
    sphere.update(camera, gl);
  }, -1);

  return (
    <primitive object={sphere} {...meshProps}>
      {children}
    </primitive>
  );
}
