// The lecture's scene in react-three-fiber from the published packages: `extend` makes the geometry and the
// material JSX elements, `<primitive>` holds the light and the mesh the trackball turns, and the frames are drawn
// through the lecture's Camera.

import { Canvas, extend, type ThreeElement, useFrame, useThree } from '@react-three/fiber';
import { Camera } from '@shadelab/camera';
import { PhongLight, ShadingMaterial } from '@shadelab/material';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import { Trackball } from '@shadelab/trackball';
import { StrictMode, useEffect, useLayoutEffect, useMemo } from 'react';
import { createRoot } from 'react-dom/client';
import { Mesh } from 'three';

extend({ SubdivisionSphereGeometry, ShadingMaterial });

declare module '@react-three/fiber' {
  interface ThreeElements {
    subdivisionSphereGeometry: ThreeElement<typeof SubdivisionSphereGeometry>;
    shadingMaterial: ThreeElement<typeof ShadingMaterial>;
  }
}

/**
 * Renders through the lecture's Camera: a `useFrame` with a positive priority takes over rendering. (r3f's own
 * camera slot, `<Canvas camera>` and `set({ camera })`, is typed for three's PerspectiveCamera and
 * OrthographicCamera only.) The aspect follows the canvas.
 */
function useLectureCamera(): Camera {
  const size = useThree((state) => state.size);
  const invalidate = useThree((state) => state.invalidate);
  const camera = useMemo(() => {
    const c = new Camera();
    c.lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
    c.setPerspective(90, 1, 0.1, 10);
    return c;
  }, []);
  useLayoutEffect(() => {
    camera.setAspect(size.width / size.height);
    invalidate();
  }, [camera, size, invalidate]);
  useFrame(({ gl, scene }) => gl.render(scene, camera), 1);
  return camera;
}

function LectureSphere() {
  const gl = useThree((state) => state.gl);
  const camera = useLectureCamera();
  const invalidate = useThree((state) => state.invalidate);
  const light = useMemo(() => {
    const l = new PhongLight({ ambient: [0.2, 0.2, 0.2], diffuse: [1, 1, 1], specular: [0.8, 0.8, 0.8] });
    l.position.set(-5, 10, 20);
    return l;
  }, []);
  const mesh = useMemo(() => new Mesh(), []);
  // Create in useMemo, connect and dispose in useEffect (as drei does with three's controls).
  const trackball = useMemo(() => new Trackball(mesh, null, { camera }), [mesh, camera]);
  useEffect(() => {
    const onChange = () => invalidate();
    trackball.connect(gl.domElement);
    trackball.addEventListener('change', onChange);
    return () => {
      trackball.removeEventListener('change', onChange);
      trackball.dispose();
    };
  }, [trackball, gl, invalidate]);
  return (
    <>
      <primitive object={light} />
      <primitive object={mesh} scale={[2, 1, 2]}>
        <subdivisionSphereGeometry args={[{ level: 6, base: 'tetrahedron' }]} />
        <shadingMaterial args={[{ shading: 'phong', lighting: 'phong', lights: [light] }]} />
      </primitive>
    </>
  );
}

createRoot(document.getElementById('root')!).render(
  <StrictMode>
    <Canvas frameloop="demand" dpr={1} gl={{ antialias: false }}>
      <LectureSphere />
    </Canvas>
  </StrictMode>,
);
