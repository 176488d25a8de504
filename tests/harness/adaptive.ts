// Harness for tests/adaptive.spec.ts (issue 25): AdaptiveShading's honesty against the full-detail Phong picture
// of the same scene (a field of subdivision spheres and a field of torus knots, perspective and orthographic,
// one white DirectionalLight of intensity π: Id = Is = 1, the error model's default light), and 1,000 moving
// instances counted in renderer.info and in their groups' attribute versions.
import { ShadingMaterial } from '@shadelab/material';
import { AdaptiveShading } from '@shadelab/material/adaptive';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import {
  type BufferGeometry,
  type Camera,
  DirectionalLight,
  InstancedMesh,
  Matrix4,
  Mesh,
  OrthographicCamera,
  PerspectiveCamera,
  Scene,
  TorusKnotGeometry,
  WebGLRenderer,
} from 'three';
import { readCanvas } from './lib/pixels';

export type Field = 'spheres' | 'knots';
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

const geometries: Record<Field, BufferGeometry> = {
  spheres: new SubdivisionSphereGeometry({ base: 'icosahedron', level: 4 }),
  knots: new TorusKnotGeometry(0.8, 0.28, 96, 12),
};

/** A field of 5 × 4 × 3 objects receding in depth, apart (no overlap on screen from the front). */
function field(kind: Field): { scene: Scene; meshes: Mesh[] } {
  const scene = new Scene();
  scene.add(light());
  const material = new ShadingMaterial({ ka: 0.15, kd: [0.7, 0.45, 0.3], ks: 0.5, shininess: 40 });
  const meshes: Mesh[] = [];
  for (let z = 0; z < 3; z++) {
    for (let y = 0; y < 4; y++) {
      for (let x = 0; x < 5; x++) {
        const m = new Mesh(geometries[kind], material);
        const spread = 1 + z * 1.6;
        m.position.set((x - 2) * 2.6 * spread, (y - 1.5) * 2.6 * spread, -z * 14);
        m.rotation.set(0.3 * x, 0.5 * y, 0.2 * z);
        m.scale.setScalar(1 - 0.2 * ((x + y) % 3));
        scene.add(m);
        meshes.push(m);
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

function honesty(kind: Field, cameraKind: CameraKind, budget: number): HonestyReport {
  const { scene, meshes } = field(kind);
  const cam = camera(cameraKind);
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
  const deltas: number[] = [];
  for (let i = 0; i < reference.length; i += 4) {
    const bg = (p: Uint8Array) => p[i] === 0 && p[i + 1] === 0 && p[i + 2] === 0;
    if (bg(reference) && bg(picture)) continue;
    deltas.push(
      Math.max(
        Math.abs(reference[i] - picture[i]),
        Math.abs(reference[i + 1] - picture[i + 1]),
        Math.abs(reference[i + 2] - picture[i + 2]),
      ),
    );
  }
  deltas.sort((a, b) => a - b);
  const drawn = deltas.length;
  return {
    drawn,
    p99: drawn ? deltas[Math.min(drawn - 1, Math.floor(0.99 * drawn))] : 0,
    over: drawn ? deltas.filter((d) => d > budget).length / drawn : 0,
    max: drawn ? deltas[drawn - 1] : 0,
    choices,
  };
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
  const drawnInstances = adaptive.groupsOf(im).reduce((s, g) => s + g.count, 0);
  adaptive.dispose();
  return { frames, maxCalls, maxGroups, maxUploads, instances: drawnInstances };
}

declare global {
  interface Window {
    adaptiveHarness: {
      honesty(field: Field, camera: CameraKind, budget: number): HonestyReport;
      instances(frames: number): InstancesReport;
    };
  }
}

window.adaptiveHarness = { honesty, instances };
document.body.dataset.ready = '1';
