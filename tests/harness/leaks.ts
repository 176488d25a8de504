// Harness for tests/reliability.spec.ts (issue 8, no leaks): creates, renders and disposes each geometry, material
// and control many times and reports renderer.info.memory, renderer.info.programs and the DOM listener count
// (counted by the wrapper main.ts installs before this page's module runs).
import { Camera, CameraMovement } from '@shadelab/camera';
import { PhongLight, type Shading, ShadingMaterial } from '@shadelab/material';
import { createOutline, OutlineMaterial } from '@shadelab/material/outline';
import { type SphereBase, SubdivisionSphereGeometry } from '@shadelab/sphere';
import { Trackball } from '@shadelab/trackball';
import {
  type BufferGeometry,
  type Material,
  Mesh,
  MeshBasicMaterial,
  PerspectiveCamera,
  Scene,
  WebGLRenderer,
} from 'three';

declare global {
  interface Window {
    __listenerCount: () => number;
    leaks: { kinds: readonly LeakKind[]; run: (kind: LeakKind, cycles: number) => LeakReport };
  }
}

/** What one run creates, renders and disposes. */
export type LeakKind =
  | 'SubdivisionSphereGeometry'
  | 'ShadingMaterial'
  | 'ShadingMaterial (new variants)'
  | 'OutlineMaterial'
  | 'PhongLight'
  | 'Camera + CameraMovement'
  | 'Trackball';

/** The counts that must come back to their baseline. */
export interface LeakCounts {
  geometries: number;
  textures: number;
  programs: number;
  listeners: number;
}

export interface LeakReport {
  kind: LeakKind;
  cycles: number;
  before: LeakCounts;
  /** The largest value of each count seen while drawing (what a cycle holds while alive). */
  peak: LeakCounts;
  after: LeakCounts;
  /** Frames rendered (one per cycle at least). */
  frames: number;
}

const canvas = document.getElementById('viewport') as HTMLCanvasElement;
const renderer = new WebGLRenderer({ canvas, antialias: false });
renderer.setPixelRatio(1);
renderer.setSize(128, 128, false);

const scene = new Scene();
const view = new PerspectiveCamera(45, 1, 0.1, 100);
view.position.set(0, 0, 4);
const light = new PhongLight({ attenuation: { a: 1, b: 0.02, c: 0 } });
light.position.set(3, 4, 5);
scene.add(light);
const baseGeometry = new SubdivisionSphereGeometry({ level: 2 });
// Flat shading reads each triangle's own vertices: a non-indexed sphere.
const flatGeometry = new SubdivisionSphereGeometry({ level: 2, normals: 'flat' });
const sphereFor = (shading: Shading) => (shading === 'flat' ? flatGeometry : baseGeometry);
const basic = new MeshBasicMaterial();
let frames = 0;
let peak: LeakCounts | null = null;

function counts(): LeakCounts {
  return {
    geometries: renderer.info.memory.geometries,
    textures: renderer.info.memory.textures,
    programs: renderer.info.programs?.length ?? 0,
    listeners: window.__listenerCount(),
  };
}

function draw(object: Mesh | null, camera: PerspectiveCamera | Camera = view): void {
  if (object) scene.add(object);
  renderer.render(scene, camera);
  frames++;
  if (peak) {
    const now = counts();
    for (const k of Object.keys(peak) as (keyof LeakCounts)[]) peak[k] = Math.max(peak[k], now[k]);
  }
  if (object) scene.remove(object);
}

const SHADINGS: readonly Shading[] = ['flat', 'gouraud', 'phong'];
const BASES: readonly SphereBase[] = ['tetrahedron', 'octahedron', 'icosahedron'];

// Materials that keep each reused variant's program alive, so a run measures what a new material leaves
// behind, not program compile times (the 'new variants' run compiles and releases its own).
const pins = SHADINGS.map(
  (shading) => new Mesh(sphereFor(shading), new ShadingMaterial({ shading, lights: [light] })),
);
for (const pin of pins) draw(pin);
const outlinePin = new Mesh(baseGeometry, new OutlineMaterial());
draw(outlinePin);
const basicPins = [baseGeometry, new SubdivisionSphereGeometry({ level: 0, normals: 'none' })].map(
  (geometry) => new Mesh(geometry, basic),
);
for (const pin of basicPins) draw(pin);

/** One create → render → dispose cycle of each kind. */
const cycle: Record<LeakKind, (i: number) => void> = {
  SubdivisionSphereGeometry: (i) => {
    const geometry = new SubdivisionSphereGeometry({
      level: i % 4,
      base: BASES[i % 3],
      normals: i % 2 ? 'smooth' : 'none',
    });
    draw(new Mesh(geometry, basic));
    geometry.dispose();
  },
  ShadingMaterial: (i) => {
    // Flat shading reads a per-geometry texture: give it a new geometry every time, too.
    const shading = SHADINGS[i % 3];
    const normals = shading === 'flat' ? 'flat' : 'smooth';
    const geometry = new SubdivisionSphereGeometry({ level: 1 + (i % 2), normals });
    const material = new ShadingMaterial({ shading, lights: [light], shininess: 1 + i });
    draw(new Mesh(geometry, material));
    material.dispose();
    geometry.dispose();
  },
  'ShadingMaterial (new variants)': (i) => {
    // celBands is part of the variant: each of these compiles a program, which disposing must release.
    const shading = SHADINGS[i % 3];
    const material = new ShadingMaterial({ shading, celBands: 2 + (i % 50), lights: [light] });
    draw(new Mesh(sphereFor(shading), material));
    material.dispose();
  },
  OutlineMaterial: (i) => {
    const mesh = new Mesh(baseGeometry, basic);
    const outline = createOutline(mesh as Mesh<BufferGeometry, Material>, { thickness: 0.01 + i * 1e-5 });
    draw(mesh);
    mesh.remove(outline);
    outline.material.dispose();
  },
  PhongLight: (i) => {
    // A second light changes the material's variant (the light count is a define) and back again.
    const extra = new PhongLight({ attenuation: { a: 1, b: 0, c: i * 1e-6 } });
    extra.position.set(-3, 2, 4);
    scene.add(extra);
    const pin = pins[i % 3]!;
    pin.material.phongLights = [light, extra];
    draw(pin);
    pin.material.phongLights = [light];
    draw(pin);
    scene.remove(extra);
  },
  'Camera + CameraMovement': (i) => {
    const camera = new Camera({ aspect: 1 });
    camera.lookAt([0, 0, 4 + (i % 5)], [0, 0, 0], [0, 1, 0]);
    const movement = new CameraMovement(camera, canvas);
    canvas.dispatchEvent(new KeyboardEvent('keydown', { code: 'KeyW' }));
    draw(pins[i % 3], camera);
    movement.dispose();
  },
  Trackball: (i) => {
    const mesh = new Mesh(baseGeometry, basic);
    const trackball = new Trackball(mesh, canvas, { camera: view });
    const at = (x: number, y: number) => ({ pointerId: 1, button: 0, clientX: x, clientY: y, bubbles: true });
    canvas.dispatchEvent(new PointerEvent('pointerdown', at(60, 60)));
    document.dispatchEvent(new PointerEvent('pointermove', at(70, 64)));
    // Every other cycle is disposed in the middle of a drag: the document listeners must go too.
    if (i % 2) document.dispatchEvent(new PointerEvent('pointerup', at(70, 64)));
    canvas.dispatchEvent(new WheelEvent('wheel', { deltaY: 10, cancelable: true }));
    draw(mesh);
    trackball.dispose();
  },
};

window.leaks = {
  kinds: Object.keys(cycle) as LeakKind[],
  run(kind, cycles) {
    const before = counts();
    peak = { ...before };
    const start = frames;
    for (let i = 0; i < cycles; i++) cycle[kind](i);
    const seen = peak;
    peak = null;
    draw(null);
    return { kind, cycles, before, peak: seen, after: counts(), frames: frames - start };
  },
};
canvas.dataset.ready = 'true';
