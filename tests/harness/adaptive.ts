// Harness for tests/adaptive.spec.ts (issue 25): AdaptiveShading's honesty against the full-detail Phong picture
// of the same scene (a field of subdivision spheres, a field of torus knots and a field of a loaded glTF model,
// perspective and orthographic, one white DirectionalLight of intensity π: Id = Is = 1, the error model's default
// light), and 1,000 moving instances counted in renderer.info and in their groups' attribute versions.
// The model: three meshes built in code (a lathed vase, a torus, a bumpy icosphere: three's geometries with
// MeshStandardMaterials), exported with three's GLTFExporter (binary GLB, nothing downloaded), loaded back with
// GLTFLoader and given ShadingMaterials by swapMaterials, as an app would load one.
import { ShadingMaterial, swapMaterials } from '@shadelab/material';
import { AdaptiveShading, pictureError } from '@shadelab/material/adaptive';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import {
  type BufferGeometry,
  type Camera,
  DirectionalLight,
  Group,
  IcosahedronGeometry,
  InstancedMesh,
  LatheGeometry,
  Matrix4,
  Mesh,
  MeshStandardMaterial,
  type Object3D,
  OrthographicCamera,
  PerspectiveCamera,
  Scene,
  TorusGeometry,
  TorusKnotGeometry,
  Vector2,
  WebGLRenderer,
} from 'three';
import { GLTFExporter } from 'three/addons/exporters/GLTFExporter.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { readCanvas } from './lib/pixels';

export type Field = 'spheres' | 'knots' | 'model';
export type CameraKind = 'perspective' | 'orthographic';

export interface HonestyReport {
  /** Pixels drawn (covered in either picture). */
  drawn: number;
  /** 99th percentile of the per-pixel max |Δ| over RGB across the drawn pixels, 8-bit levels. */
  p99: number;
  /** Fraction of the drawn pixels whose max |Δ| exceeds the budget. */
  over: number;
  /** Largest |Δ|. */
  max: number;
  /** How many objects took each choice. */
  choices: Record<string, number>;
}

export interface InstancesReport {
  frames: number;
  maxCalls: number;
  maxGroups: number;
  /** The most attribute uploads (instanceMatrix version bumps over the groups) in one frame. */
  maxUploads: number;
  /** Instances drawn in the last frame (over the groups). */
  instances: number;
}

const W = 320;
const H = 240;
const canvas = document.getElementById('viewport') as HTMLCanvasElement;
const renderer = new WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setSize(W, H, false);
renderer.setClearColor(0x000000, 1);

function light(): DirectionalLight {
  const l = new DirectionalLight(0xffffff, Math.PI);
  l.position.set(-0.4, 0.6, 1);
  return l;
}

const geometries: Record<Exclude<Field, 'model'>, BufferGeometry> = {
  spheres: new SubdivisionSphereGeometry({ base: 'icosahedron', level: 4 }),
  knots: new TorusKnotGeometry(0.8, 0.28, 96, 12),
};

/** The model as a tool would write it: three meshes of three's geometries, about one unit across together. */
function modelSource(): Group {
  const group = new Group();
  group.name = 'model';
  const profile = Array.from({ length: 12 }, (_, i) => {
    const t = i / 11;
    return new Vector2(0.05 + 0.35 * Math.sin(Math.PI * t) + 0.1 * t, 1.1 * t - 0.55);
  });
  const vase = new Mesh(
    new LatheGeometry(profile, 32),
    new MeshStandardMaterial({ color: 0xb07050, roughness: 0.4 }),
  );
  vase.name = 'vase';
  vase.position.x = -0.55;
  const ring = new Mesh(
    new TorusGeometry(0.32, 0.11, 16, 48),
    new MeshStandardMaterial({ color: 0x6080c0, roughness: 0.3 }),
  );
  ring.name = 'ring';
  ring.position.set(0.4, 0.3, 0);
  ring.rotation.x = 0.8;
  const bumps = new IcosahedronGeometry(0.3, 3);
  const p = bumps.getAttribute('position');
  for (let i = 0; i < p.count; i++) {
    const k = 1 + 0.08 * Math.sin(9 * p.getX(i)) * Math.cos(7 * p.getY(i));
    p.setXYZ(i, p.getX(i) * k, p.getY(i) * k, p.getZ(i) * k);
  }
  bumps.computeVertexNormals();
  const rock = new Mesh(bumps, new MeshStandardMaterial({ color: 0x90a060, roughness: 0.6 }));
  rock.name = 'rock';
  rock.position.set(0.4, -0.35, 0);
  group.add(vase, ring, rock);
  return group;
}

/** The loaded model: the GLB's scene, as GLTFLoader gives it (cloned per field slot, then swapped). */
const loaded = await new GLTFLoader().parseAsync(
  (await new GLTFExporter().parseAsync(modelSource(), { binary: true })) as ArrayBuffer,
  '',
);

/** The meshes GLTFLoader gave back (their names, vertex counts): what the test checks was loaded. */
function loadedModel(): { name: string; vertices: number; material: string }[] {
  const out: { name: string; vertices: number; material: string }[] = [];
  loaded.scene.traverse((o) => {
    if ((o as Mesh).isMesh) {
      const m = o as Mesh;
      out.push({
        name: m.name,
        vertices: m.geometry.getAttribute('position').count,
        material: (m.material as { type: string }).type,
      });
    }
  });
  return out;
}

/** One slot of a field: a mesh of `kind`, or a clone of the loaded model with ShadingMaterials swapped in. */
function item(kind: Field, material: ShadingMaterial): { object: Object3D; meshes: Mesh[] } {
  if (kind !== 'model') {
    const m = new Mesh(geometries[kind], material);
    return { object: m, meshes: [m] };
  }
  const clone = loaded.scene.clone(true);
  swapMaterials(clone);
  const meshes: Mesh[] = [];
  clone.traverse((o) => {
    if ((o as Mesh).isMesh) meshes.push(o as Mesh);
  });
  return { object: clone, meshes };
}

/** A field of 5 × 4 × 3 objects receding in depth, apart (no overlap on screen from the front). */
function field(kind: Field): { scene: Scene; meshes: Mesh[] } {
  const scene = new Scene();
  scene.add(light());
  const material = new ShadingMaterial({ ka: 0.15, kd: [0.7, 0.45, 0.3], ks: 0.5, shininess: 40 });
  const meshes: Mesh[] = [];
  for (let z = 0; z < 3; z++) {
    for (let y = 0; y < 4; y++) {
      for (let x = 0; x < 5; x++) {
        const { object: m, meshes: parts } = item(kind, material);
        const spread = 1 + z * 1.6;
        m.position.set((x - 2) * 2.6 * spread, (y - 1.5) * 2.6 * spread, -z * 14);
        m.rotation.set(0.3 * x, 0.5 * y, 0.2 * z);
        m.scale.setScalar((1 - 0.2 * ((x + y) % 3)) * (kind === 'model' ? 1.6 : 1));
        scene.add(m);
        meshes.push(...parts);
      }
    }
  }
  return { scene, meshes };
}

function camera(kind: CameraKind): Camera {
  const c =
    kind === 'perspective'
      ? new PerspectiveCamera(60, W / H, 0.5, 200)
      : new OrthographicCamera(-10, 10, 7.5, -7.5, 0.5, 200);
  c.position.set(0, 0, 12);
  c.lookAt(0, 0, -10);
  c.updateMatrixWorld();
  return c;
}

function honesty(kind: Field, cameraKind: CameraKind, budget: number, zoom = 1): HonestyReport {
  const { scene, meshes } = field(kind);
  const cam = camera(cameraKind);
  if (cam instanceof OrthographicCamera) {
    cam.zoom = zoom;
    cam.updateProjectionMatrix();
  }
  renderer.render(scene, cam);
  const reference = readCanvas(renderer, W, H);
  const adaptive = new AdaptiveShading({ maxError: budget });
  for (const m of meshes) adaptive.add(m);
  adaptive.update(cam, { width: W, height: H });
  renderer.render(scene, cam);
  const picture = readCanvas(renderer, W, H);
  const choices: Record<string, number> = {};
  for (const m of meshes) {
    const c = adaptive.choiceOf(m);
    const k = `${c?.shading} ${c?.level ?? 'full'}${c?.flatPath ? ` ${c.flatPath}` : ''}`;
    choices[k] = (choices[k] ?? 0) + 1;
  }
  adaptive.dispose();
  // Drawn: not the black background in either picture.
  const bg = (p: Uint8Array, i: number) => p[4 * i] === 0 && p[4 * i + 1] === 0 && p[4 * i + 2] === 0;
  const error = pictureError(reference, picture, budget, (i) => !bg(reference, i) || !bg(picture, i));
  return { ...error, choices };
}

function instances(frames: number): InstancesReport {
  const n = 1000;
  const scene = new Scene();
  scene.add(light());
  const im = new InstancedMesh(new SubdivisionSphereGeometry({ level: 2 }), new ShadingMaterial(), n);
  scene.add(im);
  const cam = camera('perspective');
  const m = new Matrix4();
  const place = (t: number) => {
    for (let i = 0; i < n; i++) {
      const x = ((i % 10) - 4.5) * 2.5;
      const y = ((Math.floor(i / 10) % 10) - 4.5) * 2;
      const z = -Math.floor(i / 100) * 6 - 20 * (0.5 + 0.5 * Math.sin(t * 0.7 + i * 0.37));
      m.makeTranslation(x, y, z);
      im.setMatrixAt(i, m);
    }
    im.instanceMatrix.needsUpdate = true;
  };
  const adaptive = new AdaptiveShading({ maxError: 8, model: { resolution: 32, views: 3, lights: 3 } });
  place(0);
  adaptive.add(im);
  let maxCalls = 0;
  let maxGroups = 0;
  let maxUploads = 0;
  let versions = new Map<InstancedMesh, number>();
  // What is counted is draw calls and uploads, not pixels: the frames go to a 1 × 1 drawing buffer, so that the GPU
  // does not rasterise 600 frames that nothing reads (work the next test would wait behind).
  renderer.setSize(1, 1, false);
  for (let f = 0; f < frames; f++) {
    place(f * 0.05);
    adaptive.update(cam, { width: W, height: H });
    renderer.render(scene, cam);
    maxCalls = Math.max(maxCalls, renderer.info.render.calls);
    const groups = adaptive.groupsOf(im);
    maxGroups = Math.max(maxGroups, groups.length);
    let uploads = 0;
    const next = new Map<InstancedMesh, number>();
    for (const g of im.children as InstancedMesh[]) {
      const v = g.instanceMatrix.version;
      if (v !== (versions.get(g) ?? 0)) uploads++;
      next.set(g, v);
    }
    versions = next;
    if (f > 0) maxUploads = Math.max(maxUploads, uploads);
  }
  renderer.setSize(W, H, false);
  const drawnInstances = adaptive.groupsOf(im).reduce((s, g) => s + g.count, 0);
  adaptive.dispose();
  return { frames, maxCalls, maxGroups, maxUploads, instances: drawnInstances };
}

declare global {
  interface Window {
    adaptiveHarness: {
      honesty(field: Field, camera: CameraKind, budget: number, zoom?: number): HonestyReport;
      loadedModel(): { name: string; vertices: number; material: string }[];
      instances(frames: number): InstancesReport;
    };
  }
}

window.adaptiveHarness = { honesty, instances, loadedModel };
document.body.dataset.ready = '1';
