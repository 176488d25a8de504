// Issue 14's realistic scene, shared by the benchmark pages that draw it (scene-bench.ts: ShadingMaterial against
// three's materials; swap-bench.ts: MeshPhongMaterial against the same scene after swapMaterials): 1,000
// instances (10 × 10 × 10, spacing 3) of the level-3 tetrahedron sphere with per-instance colours, three
// PointLights (decay 2) and a DirectionalLight, as three's examples light a scene, linear Fog, a 50° camera.
// Each call builds a new scene around the material it is given; the geometries are built once and shared.
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import {
  type BufferGeometry,
  Color,
  DirectionalLight,
  Fog,
  InstancedMesh,
  type Material,
  Matrix4,
  PerspectiveCamera,
  PointLight,
  Scene,
} from 'three';

/** Instances per side of the 10 × 10 × 10 lattice, and their spacing (world units; sphere radius 1). */
export const REALISTIC_SIDE = 10;
const spacing = 3;

/** The level-3 sphere (256 triangles, smooth normals), indexed as three's geometries are, and non-indexed. */
export const realisticGeometries = {
  indexed: new SubdivisionSphereGeometry({ level: 3, normals: 'smooth', indexed: true }),
  'non-indexed': new SubdivisionSphereGeometry({ level: 3, normals: 'smooth', indexed: false }),
};

/** The 1,000 instance matrices and colours, the same for every scene (no randomness). */
function fillInstances(mesh: InstancedMesh): void {
  const m = new Matrix4();
  const c = new Color();
  let i = 0;
  const side = REALISTIC_SIDE;
  const half = ((side - 1) * spacing) / 2;
  for (let x = 0; x < side; x++) {
    for (let y = 0; y < side; y++) {
      for (let z = 0; z < side; z++) {
        m.makeTranslation(x * spacing - half, y * spacing - half, z * spacing - half);
        mesh.setMatrixAt(i, m);
        mesh.setColorAt(i, c.setHSL(((x * 7 + y * 3 + z * 5) % 20) / 20, 0.6, 0.55));
        i++;
      }
    }
  }
}

/**
 * A new realistic scene whose 1,000 instances wear `material`, drawn from `geometry` (default: the indexed
 * sphere), and its camera for a canvas of aspect `aspect` (width / height).
 */
export function buildRealisticScene(
  material: Material,
  geometry: BufferGeometry = realisticGeometries.indexed,
  aspect = 1280 / 720,
): { scene: Scene; camera: PerspectiveCamera; mesh: InstancedMesh } {
  const scene = new Scene();
  scene.background = new Color(0x1a1d22);
  scene.fog = new Fog(0x1a1d22, 35, 95);
  const pointColors = [0xffe0c0, 0xc0d8ff, 0xffffff];
  const pointPositions: Array<[number, number, number]> = [
    [-20, 18, 25],
    [22, -6, 18],
    [0, 25, -10],
  ];
  for (let i = 0; i < 3; i++) {
    const light = new PointLight(pointColors[i], 400, 0, 2);
    light.position.set(...pointPositions[i]);
    scene.add(light);
  }
  const sun = new DirectionalLight(0xffffff, 0.8);
  sun.position.set(5, 10, 7);
  scene.add(sun);
  const mesh = new InstancedMesh(geometry, material, REALISTIC_SIDE ** 3);
  fillInstances(mesh);
  scene.add(mesh);
  const camera = new PerspectiveCamera(50, aspect, 0.5, 200);
  camera.position.set(30, 22, 38);
  camera.lookAt(0, 0, 0);
  return { scene, camera, mesh };
}
