// Type tests of the JSX elements @shadelab/react registers, with no `extend` or `declare module` here: importing
// the package is enough. `npx tsc -p tsconfig.test.json` fails if a case marked @ts-expect-error type-checks (the
// directive is then unused) or if a positive case does not. Not run: rendering is tested in tests/react.spec.ts.
import type { ThreeElements } from '@react-three/fiber';
import { PhongLight, ShadingMaterial } from '@shadelab/material';
import { SphereImpostorMaterial } from '@shadelab/material/impostor';
import { AutoDetailSphere, LectureCamera, Trackball, useTrackball } from '@shadelab/react';
import type { Trackball as TrackballControls } from '@shadelab/trackball';
import { Color, type Mesh, Vector3 } from 'three';

const light = new PhongLight({ ambient: 0.2 });

export const scene = (
  <>
    <LectureCamera makeDefault eye={[0, 0, 3]} at={[0, 0, 0]} up={[0, 1, 0]} fovy={90} near={0.1} far={10} />
    <phongLight
      ambient={[0.2, 0.2, 0.2]}
      diffuse="#ffffff"
      specular={new Color(0.8, 0.8, 0.8)}
      position={[-5, 10, 20]}
    />
    <phongLight
      args={[{ ambient: 0.2, attenuation: { a: 1, b: 0.1, c: 0 } }]}
      attenuation={{ a: 1, b: 0, c: 0.01 }}
    />
    <Trackball
      makeDefault
      rotateSpeed={2}
      mapping="arcball"
      onChange={(e) => e.target.getMatrix()}
      onEnd={(e) => e.type}
    >
      <mesh scale={[2, 1, 2]}>
        <subdivisionSphereGeometry args={[{ level: 6, base: 'tetrahedron', normals: 'none' }]} />
        <shadingMaterial
          shading="phong"
          lighting="blinn-phong"
          ka={[0.1, 0.1, 0.1]}
          kd="#996633"
          shininess={32}
        />
      </mesh>
    </Trackball>
    <mesh>
      <subdivisionSphereGeometry />
      {/* The explicit list of lights is `phongLights`. */}
      <shadingMaterial phongLights={[light]} args={[{ shading: 'gouraud', lights: [light] }]} />
    </mesh>
    <mesh>
      <outlineMaterial thickness={0.05} color="#000000" />
    </mesh>
    <sphereImpostor args={[new SphereImpostorMaterial()]}>
      <sphereImpostorMaterial kd={[0.6, 0.35, 0.2]} />
    </sphereImpostor>
    <AutoDetailSphere maxErrorPx={0.5} bases={['icosahedron']} scale={[2, 1, 2]} position={[1, 0, 0]}>
      <shadingMaterial />
    </AutoDetailSphere>
    <autoDetailSphere args={[new ShadingMaterial(), { maxErrorPx: 1 }]} />
  </>
);

export const refused = (
  <>
    {/* @ts-expect-error three's ShaderMaterial.lights is a boolean flag, not the PhongLight list (phongLights). */}
    <shadingMaterial lights={[light]} />
    {/* @ts-expect-error not a shading */}
    <shadingMaterial shading="smooth" />
    {/* @ts-expect-error not a lighting */}
    <shadingMaterial lighting="lambert" />
    {/* @ts-expect-error a bare number would be Color.set's hex (0.2 → black), not a grey level: [0.2, 0.2, 0.2] */}
    <shadingMaterial ka={0.2} />
    {/* @ts-expect-error not a colour */}
    <phongLight diffuse={{ r: 1 }} />
    {/* @ts-expect-error a grey level number, likewise */}
    <phongLight ambient={0.2} />
    {/* @ts-expect-error shininess is a number */}
    <shadingMaterial shininess="high" />
    {/* @ts-expect-error not a PhongLight list */}
    <shadingMaterial phongLights={[new Vector3()]} />
    {/* @ts-expect-error not a sphere base */}
    <subdivisionSphereGeometry args={[{ base: 'cube' }]} />
    {/* @ts-expect-error not a ball mapping */}
    <Trackball mapping="orbit" />
    {/* @ts-expect-error fovy is a number */}
    <LectureCamera fovy="wide" />
    {/* @ts-expect-error maxErrorPx is a number */}
    <AutoDetailSphere maxErrorPx="1px" />
  </>
);

// The hook returns the trackball; R3F's own elements keep their types.
export function useTurned(mesh: Mesh): TrackballControls {
  return useTrackball(mesh, { rotateSpeed: 1, target: new Vector3(0, 0, 0) });
}
export const meshProps: ThreeElements['mesh'] = { position: [0, 0, 0] };
