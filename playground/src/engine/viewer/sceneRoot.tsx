/**
 * The viewer's scene as React Three Fiber composes it with `@shadelab/react`: an R3F root on the viewer's canvas
 * makes the renderer (with exactly the parameters the pictures were made with) and mounts the lecture's sphere as
 * JSX: one `<Trackball>` turning the single view's `<mesh>` with its `<shadingMaterial>`, the `<sphereImpostor>`,
 * and the compare view's meshes (one per column, each with its column's material), so that one drag turns all
 * four cells. R3F drives every frame: the viewer calls {@link SceneRoot.frame} on demand, which advances the root
 * (`useTrackball`'s damping steps at priority -1) and then draws through a `useFrame` at priority 1 that takes
 * the render over (the single view, or each cell with its column's mesh shown).
 *
 * Why an R3F root (`createRoot`) and not `<Canvas>`: `<Canvas>` wraps its own canvas in two divs and sizes it in
 * pixels; the viewer's canvas is the app's (its label, focus, keys and test id) and CSS sizes it, so the layout
 * and every picture stay as they were.
 */
import {
  advance,
  createRoot,
  extend,
  flushSync,
  type ReconcilerRoot,
  type RootState,
  unmountComponentAtNode,
  useFrame,
  useThree,
} from '@react-three/fiber';
import { type Camera, depthBufferParameters } from '@shadelab/camera';
import type { ShadingMaterial } from '@shadelab/material';
import { type SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { Trackball as TrackballElement } from '@shadelab/react';
import type { Trackball } from '@shadelab/trackball';
import { type RefObject, useLayoutEffect, useMemo } from 'react';
import * as THREE from 'three';
import type { DepthMode } from '../../state/schema';
import type { DemoScene } from '../scenes';
import { COMPARE_COLUMNS } from './layout';

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
  /** The compare view's meshes, one per column of `COMPARE_COLUMNS` (its material is that column's). */
  columns: THREE.Mesh<THREE.BufferGeometry, ShadingMaterial>[];
}

/** What the JSX's refs fill: the objects, and the compare view's meshes by column. */
type Into = Partial<LectureSphereObjects> & Pick<LectureSphereObjects, 'columns'>;

/** Draws one frame (what the frame's `useFrame` calls; the viewer's draws use its own renderer and camera). */
export type DrawFrame = () => void;

/** The values the JSX sets from the state. */
export interface LectureSphereProps {
  /** The model's scale (x, y, z) on the mesh (state `model.scale`). */
  scale: readonly [number, number, number];
  /** The sphere's radius (state `sphere.radius`): the impostor, a unit sphere, is scaled by it too. */
  radius: number;
  /** The scene picker's scene, under the trackball beside the (then hidden) sphere; null for the sphere. */
  picked: DemoScene | null;
}

/**
 * A picked scene under the trackball: its objects (built in code by `src/engine/scenes/`: instance matrices,
 * bones, textures made from numbers) mounted as a `<primitive>`, and what it sets on the scene and the renderer
 * (fog, clipping planes) for as long as it is mounted. Freed by the viewer after it unmounts (R3F does not
 * dispose a primitive).
 */
function PickedSceneObjects({ picked }: { picked: DemoScene }) {
  const scene = useThree((state) => state.scene);
  const gl = useThree((state) => state.gl) as THREE.WebGLRenderer;
  useLayoutEffect(() => {
    picked.enter?.(scene, gl);
    return () => picked.leave?.(scene, gl);
  }, [picked, scene, gl]);
  // An animated scene (a model's clip) steps by each frame's time, before the frame is drawn (priority 1).
  useFrame((_, delta) => picked.step?.(delta));
  return <primitive object={picked.root} />;
}

/**
 * The scene under the one trackball (the lecture's sphere, the compare view's meshes, a picked scene), the
 * frame's draw, and the sphere's scale from the state. The other values (material options,
 * geometry, the trackball's options) are set by `applyState.ts`, not as props: a value a package refuses must be
 * reported for its section while the last good one stays on screen, and a setter that throws inside R3F's commit
 * would unmount the tree. (A scale cannot be refused: the state's parser took finite numbers.)
 */
function LectureSphereScene({
  into,
  draw,
  scale: [x, y, z],
  radius,
  picked,
}: LectureSphereProps & { into: Into; draw: RefObject<DrawFrame | null> }) {
  const impostorMaterial = useMemo(() => new SphereImpostorMaterial(), []);
  const keep =
    <K extends keyof LectureSphereObjects>(key: K) =>
    (value: LectureSphereObjects[K] | null) => {
      if (value) into[key] = value;
    };
  // Priority 1: R3F does not render by itself; this draws the frame (the viewer's draw for this frame).
  useFrame(() => draw.current?.(), 1);
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
      {COMPARE_COLUMNS.map((column, i) => (
        <mesh
          key={column.label}
          name={`compare: ${column.label}`}
          visible={false}
          scale={[x, y, z]}
          ref={(mesh: LectureSphereObjects['columns'][number] | null) => {
            if (mesh) into.columns[i] = mesh;
          }}
        >
          <shadingMaterial />
        </mesh>
      ))}
      {picked && <PickedSceneObjects key={picked.root.uuid} picked={picked} />}
    </TrackballElement>
  );
}

/**
 * The R3F root of each canvas until R3F has torn it down. React's StrictMode (in development) disposes a viewer
 * and makes a new one on the same canvas at once; R3F keeps the root's store and renderer for that (its teardown
 * waits a commit), and a viewer takes the same root again instead of asking `createRoot` for a second one, which
 * R3F refuses with a warning.
 */
const rootsOfCanvases = new WeakMap<HTMLCanvasElement, ReconcilerRoot<HTMLCanvasElement>>();

/** three's message for R3F's `new THREE.Clock()` in every store it makes (three deprecated Clock for Timer). */
const CLOCK_DEPRECATION = 'THREE.Clock: This module has been deprecated.';

/**
 * `canvas`'s R3F root: the one R3F still holds, or a new one. R3F 9 makes its store's clock a `THREE.Clock`, so
 * three warns of the deprecation on every new root, about code neither this app nor its users can change: that
 * one message is dropped while the store is made, and three's console is as it was after.
 */
function rootOf(canvas: HTMLCanvasElement): ReconcilerRoot<HTMLCanvasElement> {
  const held = rootsOfCanvases.get(canvas);
  if (held) return held;
  const previous = THREE.getConsoleFunction();
  THREE.setConsoleFunction((type, message, ...params) => {
    if (message.startsWith(CLOCK_DEPRECATION)) return;
    if (previous) previous(type, message, ...params);
    else console[type](message, ...params);
  });
  try {
    const root = createRoot(canvas);
    rootsOfCanvases.set(canvas, root);
    return root;
  } finally {
    THREE.setConsoleFunction(previous as Parameters<typeof THREE.setConsoleFunction>[0]);
  }
}

/** The R3F root of one canvas: its renderer, its scene and the single view's objects. */
export class SceneRoot {
  readonly renderer: THREE.WebGLRenderer;
  readonly scene: THREE.Scene;
  private readonly root: ReconcilerRoot<HTMLCanvasElement>;
  private readonly canvas: HTMLCanvasElement;
  /** The objects the lecture sphere's JSX made (filled by its refs). */
  private readonly into: Into = { columns: [] };
  /** The props last rendered. */
  private props: LectureSphereProps = { scale: [1, 1, 1], radius: 1, picked: null };
  /** What the frame's `useFrame` draws, set for the length of one {@link SceneRoot.frame}. */
  private readonly draw: RefObject<DrawFrame | null> = { current: null };
  private readonly state: () => RootState;
  /** R3F's clock, seconds: advanced by the time between frames, at most 0.1 s a frame (after a pause). */
  private clock = 0;
  private lastFrame = 0;

  /**
   * Makes the renderer: no antialiasing, the drawing buffer kept (PNG export, the tests' readPixels), the depth
   * buffer `depth` asks for, pixel ratio 1, three's default colour space (sRGB) and no tone mapping (`flat`).
   * R3F renders only when the viewer advances it (`frameloop: 'never'`, {@link SceneRoot.frame}): on demand.
   * No R3F pointer events either (nothing in the scene is picked by pointer; the gizmo and the trackball listen
   * on the canvas themselves). The camera is the viewer's, whose projection the viewer sets per cell (`manual`).
   */
  constructor(canvas: HTMLCanvasElement, depth: DepthMode, camera: Camera) {
    this.canvas = canvas;
    this.root = rootOf(canvas);
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
    const store = this.root.render(null);
    this.state = () => store.getState();
    const state = store.getState();
    this.renderer = renderer ?? (state.gl as THREE.WebGLRenderer);
    this.scene = state.scene;
    // R3F writes its size into the canvas's style in pixels; CSS sizes this canvas (the viewer fits the drawing
    // buffer to it before each frame), so the style goes back to the stylesheet's.
    canvas.style.width = '';
    canvas.style.height = '';
  }

  /** Mounts the lecture's sphere (committed at once: its objects exist on return), unscaled. */
  mountLectureSphere(): LectureSphereObjects {
    this.setLectureSphere({});
    const { trackball, pivot, mesh, material, impostor, columns } = this.into;
    if (
      !trackball ||
      !pivot ||
      !mesh ||
      !material ||
      !impostor ||
      columns.length !== COMPARE_COLUMNS.length
    ) {
      throw new Error('The lecture sphere did not mount.');
    }
    return { trackball, pivot, mesh, material, impostor, columns };
  }

  /**
   * Renders the scene with `props` changed (the others as they were) and commits at once (R3F's `flushSync`):
   * what the viewer computes next from the scene (the silhouette error of automatic detail) reads the new
   * scale, and a picked scene is in place (its `enter` run, the previous one's `leave`) on return.
   */
  setLectureSphere(props: Partial<LectureSphereProps>): void {
    this.props = { ...this.props, ...props };
    const rendered = this.props;
    flushSync(() => this.root.render(<LectureSphereScene into={this.into} draw={this.draw} {...rendered} />));
  }

  /**
   * One frame, now: advances R3F's clock (each `useFrame` gets the time since the last frame, at most 0.1 s:
   * `useTrackball` steps a damped spin by it) and draws the frame with `draw`.
   */
  frame(draw: DrawFrame): void {
    const now = performance.now();
    this.clock += this.lastFrame ? Math.min(0.1, (now - this.lastFrame) / 1000) : 0;
    this.lastFrame = now;
    this.draw.current = draw;
    try {
      advance(this.clock, false, this.state());
    } finally {
      this.draw.current = null;
    }
  }

  /**
   * Unmounts the scene and releases the renderer (R3F made it, R3F frees it, after a commit). A viewer made on
   * the canvas before then takes the root back, and R3F keeps it.
   */
  unmount(): void {
    const { canvas, root } = this;
    unmountComponentAtNode(canvas, () => {
      if (rootsOfCanvases.get(canvas) === root) rootsOfCanvases.delete(canvas);
    });
  }
}
