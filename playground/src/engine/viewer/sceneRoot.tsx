/**
 * The viewer's scene as React Three Fiber composes it with `@shadelab/react`: an R3F root on the viewer's canvas
 * makes the renderer (with exactly the parameters the pictures were made with) and mounts the lecture's sphere as
 * JSX (`<Trackball>` turning a `<mesh>` with a `<shadingMaterial>`, and the `<sphereImpostor>`).
 *
 * Why an R3F root (`createRoot`) and not `<Canvas>`: `<Canvas>` wraps its own canvas in two divs and sizes it in
 * pixels; the viewer's canvas is the app's (its label, focus, keys and test id) and CSS sizes it, so the layout
 * and every picture stay as they were.
 */
import { createRoot, extend, flushSync, type ReconcilerRoot } from '@react-three/fiber';
import { type Camera, depthBufferParameters } from '@shadelab/camera';
import type { ShadingMaterial } from '@shadelab/material';
import { type SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { Trackball as TrackballElement } from '@shadelab/react';
import type { Trackball } from '@shadelab/trackball';
import { useMemo } from 'react';
import * as THREE from 'three';
import type { DepthMode } from '../../state/schema';

// three's own elements (`<mesh>`): `<Canvas>` registers them all, a bare root only those it is given.
extend({ Mesh: THREE.Mesh });

/** The single view's objects, as the JSX made them (read by the viewer's parts). */
export interface LectureSphereObjects {
  /** The lecture's trackball; it turns {@link LectureSphereObjects.pivot}. */
  trackball: Trackball;
  /** The group the trackball turns: the sphere, the impostor and a picked scene sit in it. */
  pivot: THREE.Group;
  mesh: THREE.Mesh;
  /** The panel's material (its program is the one the shader editor shows). */
  material: ShadingMaterial;
  /** The ray-cast sphere, drawn instead of the mesh when `sphere.render` is 'impostor' (single view). */
  impostor: SphereImpostor;
}

/** The single view's values the JSX sets from the state. */
export interface LectureSphereProps {
  /** The model's scale (x, y, z) on the mesh (state `model.scale`). */
  scale: readonly [number, number, number];
  /** The sphere's radius (state `sphere.radius`): the impostor, a unit sphere, is scaled by it too. */
  radius: number;
}

/**
 * The lecture's sphere under the trackball, its scale from the state. The other values (material options,
 * geometry, the trackball's options) are set by `applyState.ts`, not as props: a value a package refuses must be
 * reported for its section while the last good one stays on screen, and a setter that throws inside R3F's commit
 * would unmount the tree. (A scale cannot be refused: the state's parser took finite numbers.)
 */
function LectureSphereScene({
  into,
  scale: [x, y, z],
  radius,
}: LectureSphereProps & { into: Partial<LectureSphereObjects> }) {
  const impostorMaterial = useMemo(() => new SphereImpostorMaterial(), []);
  const keep =
    <K extends keyof LectureSphereObjects>(key: K) =>
    (value: LectureSphereObjects[K] | null) => {
      if (value) into[key] = value;
    };
  return (
    <TrackballElement
      ref={(trackball) => {
        // <Trackball>'s own group (it holds the children) is what it turns.
        if (trackball) Object.assign(into, { trackball, pivot: trackball.object as THREE.Group });
      }}
    >
      <mesh ref={keep('mesh')} scale={[x, y, z]}>
        <shadingMaterial ref={keep('material')} />
      </mesh>
      <sphereImpostor
        args={[impostorMaterial]}
        visible={false}
        scale={[x * radius, y * radius, z * radius]}
        ref={keep('impostor')}
      />
    </TrackballElement>
  );
}

/** The R3F root of one canvas: its renderer, its scene and the single view's objects. */
export class SceneRoot {
  readonly renderer: THREE.WebGLRenderer;
  readonly scene: THREE.Scene;
  private readonly root: ReconcilerRoot<HTMLCanvasElement>;
  /** The objects the lecture sphere's JSX made (filled by its refs). */
  private readonly into: Partial<LectureSphereObjects> = {};

  /**
   * Makes the renderer: no antialiasing, the drawing buffer kept (PNG export, the tests' readPixels), the depth
   * buffer `depth` asks for, pixel ratio 1, three's default colour space (sRGB) and no tone mapping (`flat`).
   * R3F never renders (`frameloop: 'never'`): the viewer renders on demand, cell by cell in the compare view.
   * No R3F pointer events either (nothing in the scene is picked by pointer; the gizmo and the trackball listen
   * on the canvas themselves). The camera is the viewer's, whose projection the viewer sets per cell (`manual`).
   */
  constructor(canvas: HTMLCanvasElement, depth: DepthMode, camera: Camera) {
    this.root = createRoot(canvas);
    let renderer: THREE.WebGLRenderer | undefined;
    const width = Math.max(1, canvas.clientWidth || canvas.width);
    const height = Math.max(1, canvas.clientHeight || canvas.height);
    void this.root.configure({
      gl: ({ canvas }) => {
        renderer = new THREE.WebGLRenderer({
          canvas: canvas as HTMLCanvasElement,
          antialias: false,
          preserveDrawingBuffer: true,
          ...depthBufferParameters(depth),
        });
        return renderer;
      },
      // R3F's type names three's two cameras only; it takes any camera (`isCamera`), as LectureCamera does.
      camera: Object.assign(camera, { manual: true }) as never,
      scene: { background: new THREE.Color(0x000000) },
      frameloop: 'never',
      dpr: 1,
      flat: true,
      size: { width, height, top: 0, left: 0 },
    });
    // R3F's scene (`scene` is read from it, not given: a root that React's StrictMode unmounts and mounts again
    // in development keeps its renderer and scene, and the viewer must draw the scene the JSX is in).
    const state = this.root.render(null).getState();
    this.renderer = renderer ?? (state.gl as THREE.WebGLRenderer);
    this.scene = state.scene;
    // R3F writes its size into the canvas's style in pixels; CSS sizes this canvas (the viewer fits the drawing
    // buffer to it before each frame), so the style goes back to the stylesheet's.
    canvas.style.width = '';
    canvas.style.height = '';
  }

  /** Mounts the lecture's sphere (committed at once: its objects exist on return), unscaled. */
  mountLectureSphere(): LectureSphereObjects {
    flushSync(() => this.root.render(<LectureSphereScene into={this.into} scale={[1, 1, 1]} radius={1} />));
    const { trackball, pivot, mesh, material, impostor } = this.into;
    if (!trackball || !pivot || !mesh || !material || !impostor) {
      throw new Error('The lecture sphere did not mount.');
    }
    return { trackball, pivot, mesh, material, impostor };
  }

  /**
   * Renders the lecture's sphere with `props` and commits at once (R3F's `flushSync`): what the viewer computes
   * next from the scene (the silhouette error of automatic detail) reads the new scale.
   */
  setLectureSphere(props: LectureSphereProps): void {
    flushSync(() => this.root.render(<LectureSphereScene into={this.into} {...props} />));
  }

  /** Unmounts the scene and releases the renderer (R3F made it, R3F frees it). */
  unmount(): void {
    this.root.unmount();
  }
}
