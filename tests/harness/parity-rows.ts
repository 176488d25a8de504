// Harness of tests/material-parity.spec.ts: every row of the any-scene table as a named scene of the kit's
// toMatchAcrossRenderers, drawn with ShadingMaterial on WebGLRenderer and with ShadingNodeMaterial (the same
// options) on WebGPURenderer's WebGPU and WebGL2 backends. Each scene is a small lit object (and a ground where a
// row needs one) under three's lights or a PhongLight, as an app has it.
import {
  flatShadingGeometry,
  PhongLight,
  ShadingMaterial,
  type ShadingMaterialOptions,
} from '@shadelab/material';
import { ShadingNodeMaterial } from '@shadelab/material/webgpu';
import {
  exposeRenderers,
  registerScene,
  type SceneContext,
  type SceneSetup,
} from '@shadelab/playwright/page';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';

exposeRenderers({ PhongLight, ShadingMaterial, ShadingNodeMaterial });

type Three = SceneContext['THREE'];
type Material = InstanceType<Three['Material']>;

/** The row's material: ShadingMaterial for WebGLRenderer, ShadingNodeMaterial for WebGPURenderer. */
function shading(context: SceneContext, options: ShadingMaterialOptions): Material {
  return context.kind === 'webgl'
    ? new ShadingMaterial(options)
    : (new ShadingNodeMaterial(options as ConstructorParameters<typeof ShadingNodeMaterial>[0]) as Material);
}

/** A 4 × 4 RGBA texture of `texel(x, y)` (0 … 255 each), nearest-filtered, in `colorSpace`. */
function texture(
  THREE: Three,
  texel: (x: number, y: number) => number[],
  colorSpace: string,
): InstanceType<Three['DataTexture']> {
  const data = new Uint8Array(4 * 4 * 4);
  for (let y = 0; y < 4; y++) for (let x = 0; x < 4; x++) data.set(texel(x, y), 4 * (4 * y + x));
  const t = new THREE.DataTexture(data, 4, 4);
  t.colorSpace = colorSpace as typeof t.colorSpace;
  t.magFilter = THREE.NearestFilter;
  t.minFilter = THREE.NearestFilter;
  t.needsUpdate = true;
  return t;
}

/** Three's lights as an app has them: a point light of decay 2 and an ambient light (the drop-in mapping). */
function threeLights(THREE: Three, scene: InstanceType<Three['Scene']>): void {
  const point = new THREE.PointLight(0xffffff, 30, 0, 2);
  point.position.set(-2, 3, 4);
  scene.add(point, new THREE.AmbientLight(0xffffff, 0.4));
}

/** A camera looking at the origin from +z. */
function camera(
  THREE: Three,
  { width, height }: SceneContext,
  z = 3.4,
): InstanceType<Three['PerspectiveCamera']> {
  const c = new THREE.PerspectiveCamera(45, width / height, 0.1, 20);
  c.position.set(0, 0, z);
  return c;
}

/** One object of `geometry` with the row's options, under three's lights. */
function row(
  context: SceneContext,
  options: ShadingMaterialOptions,
  extra: {
    geometry?: InstanceType<Three['BufferGeometry']>;
    setup?: Partial<SceneSetup>;
    material?: (m: Material) => void;
  } = {},
): SceneSetup {
  const { THREE } = context;
  const scene = new THREE.Scene();
  threeLights(THREE, scene);
  const material = shading(context, { ka: 0.3, kd: [0.8, 0.6, 0.4], ks: 0.5, shininess: 24, ...options });
  extra.material?.(material);
  const geometry = (extra.geometry ?? new THREE.TorusKnotGeometry(0.8, 0.3, 96, 16)) as InstanceType<
    Three['TorusKnotGeometry']
  >;
  const mesh = new THREE.Mesh(geometry, material);
  mesh.rotation.set(0.4, 0.3, 0);
  scene.add(mesh);
  return { scene, camera: camera(THREE, context), clearColor: 0x101820, ...extra.setup };
}

/** The diffuse-only colour of the rows where WebGPURenderer has its own way. */
const OWN_WAY: ShadingMaterialOptions = { ka: [0.8, 0.6, 0.4], kd: [0.8, 0.6, 0.4], ks: 0 };

/**
 * The rows where WebGPURenderer has its own way (fog, tone mapping, blending) draw diffuse-only objects (ka = kd =
 * c, ks = 0), which three's MeshPhongMaterial (specular 0) draws with the same pixels under three's lights (the
 * drop-in mapping): with `arg.three`, every material of `setup` is replaced by that, so the spec can compare the
 * row with three's own material on each renderer.
 */
function ownWay(c: SceneContext, setup: SceneSetup): SceneSetup {
  if ((c.arg as { three?: boolean } | undefined)?.three !== true) return setup;
  setup.scene.traverse((o) => {
    const mesh = o as InstanceType<Three['Mesh']>;
    if (!mesh.isMesh) return;
    const old = mesh.material as Material & { kd: InstanceType<Three['Color']> };
    mesh.material = new c.THREE.MeshPhongMaterial({
      color: old.kd.clone(),
      specular: 0,
      opacity: old.opacity,
      transparent: old.transparent,
    });
    old.dispose();
  });
  return setup;
}

const checker = (THREE: Three) =>
  texture(
    THREE,
    (x, y) => ((x + y) % 2 === 0 ? [230, 200, 60, 255] : [40, 90, 200, 255]),
    THREE.SRGBColorSpace,
  );

registerScene('map', (c) => row(c, { map: checker(c.THREE) }));
registerScene('vertexColors', (c) => {
  const geometry = new c.THREE.TorusKnotGeometry(0.8, 0.3, 96, 16);
  const position = geometry.getAttribute('position');
  const colours = new Float32Array(position.count * 3);
  for (let i = 0; i < position.count; i++) {
    colours.set(
      [0.5 + 0.5 * Math.sin(position.getX(i) * 3), 0.6, 0.5 + 0.5 * Math.cos(position.getY(i) * 3)],
      3 * i,
    );
  }
  geometry.setAttribute('color', new c.THREE.BufferAttribute(colours, 3));
  return row(c, { vertexColors: true }, { geometry });
});
registerScene('normalMap', (c) => {
  // Bumps tilted towards ±x in alternate texels (tangent space, linear data).
  const normalMap = texture(
    c.THREE,
    (x) => (x % 2 === 0 ? [200, 128, 230, 255] : [56, 128, 230, 255]),
    c.THREE.NoColorSpace,
  );
  return row(c, { normalMap }, { geometry: new c.THREE.SphereGeometry(1.1, 48, 24) });
});
registerScene('emissive', (c) => row(c, { emissive: [0.2, 0.05, 0], emissiveMap: checker(c.THREE) }));
registerScene('alpha', (c) => {
  // opacity + transparent over a ground: blended as each renderer blends (WebGPURenderer in linear).
  const geometry = new c.THREE.SphereGeometry(1.1, 48, 24);
  const setup = row(c, { ...OWN_WAY, opacity: 0.6, transparent: true }, { geometry });
  const ground = new c.THREE.Mesh(new c.THREE.PlaneGeometry(8, 8), shading(c, { ka: 0.5, kd: 0.5, ks: 0 }));
  ground.position.z = -1.5;
  setup.scene.add(ground);
  return ownWay(c, setup);
});
registerScene('alphaTest', (c) => {
  const alphaMap = texture(
    c.THREE,
    (x, y) => {
      const a = (x + y) % 2 === 0 ? 255 : 0;
      return [a, a, a, 255];
    },
    c.THREE.NoColorSpace,
  );
  return row(c, { alphaTest: 0.5, alphaMap }, { material: (m) => (m.side = c.THREE.DoubleSide) });
});
registerScene('fog', (c) => {
  const setup = row(c, OWN_WAY);
  (setup.scene as InstanceType<Three['Scene']>).fog = new c.THREE.Fog(0x101820, 2.5, 4.5);
  return ownWay(c, setup);
});
registerScene('fogExp2', (c) => {
  const setup = row(c, OWN_WAY);
  (setup.scene as InstanceType<Three['Scene']>).fog = new c.THREE.FogExp2(0x101820, 0.25);
  return ownWay(c, setup);
});
registerScene('toneMapping', (c) =>
  ownWay(
    c,
    row(c, OWN_WAY, { setup: { toneMapping: c.THREE.ACESFilmicToneMapping, toneMappingExposure: 1.4 } }),
  ),
);
registerScene('linearOutput', (c) =>
  row(c, {}, { setup: { outputColorSpace: c.THREE.LinearSRGBColorSpace } }),
);
registerScene('threeLights', (c) => {
  // The five kinds together.
  const { THREE } = c;
  const scene = new THREE.Scene();
  const point = new THREE.PointLight(0xff8040, 20, 10, 2);
  point.position.set(-2, 2, 3);
  const spot = new THREE.SpotLight(0x40ff80, 40, 0, 0.5, 0.3, 2);
  spot.position.set(2, 2, 3);
  const directional = new THREE.DirectionalLight(0x8080ff, 1.5);
  directional.position.set(0, -2, 3);
  scene.add(point, spot, spot.target, directional, directional.target);
  scene.add(new THREE.AmbientLight(0x404040, 1), new THREE.HemisphereLight(0x202040, 0x402020, 1));
  scene.add(
    new THREE.Mesh(
      new THREE.SphereGeometry(1.1, 48, 24),
      shading(c, { ka: 0.5, kd: 0.7, ks: 0.4, shininess: 20 }),
    ),
  );
  return { scene, camera: camera(THREE, c), clearColor: 0x101820 };
});
registerScene('phongLights', (c) => {
  const { THREE } = c;
  const scene = new THREE.Scene();
  const a = new PhongLight({
    ambient: 0.1,
    diffuse: [1, 0.8, 0.6],
    specular: 0.8,
    attenuation: { a: 1, b: 0.1, c: 0.02 },
  });
  a.position.set(-3, 3, 4);
  const b = new PhongLight({ ambient: 0.05, diffuse: [0.3, 0.4, 1], specular: 0.5 });
  b.position.set(3, -1, 2);
  scene.add(a, b);
  scene.add(
    new THREE.Mesh(
      new THREE.TorusKnotGeometry(0.8, 0.3, 96, 16),
      shading(c, { shininess: 32, lights: [a, b] }),
    ),
  );
  return { scene, camera: camera(THREE, c), clearColor: 0x101820 };
});
for (const kind of ['flatSoup', 'flatPrepared', 'gouraud', 'cel'] as const) {
  registerScene(kind, (c) => {
    const base = new c.THREE.IcosahedronGeometry(1.1, 1);
    if (kind === 'flatSoup') return row(c, { shading: 'flat' }, { geometry: base });
    if (kind === 'flatPrepared') {
      // flatShadingGeometry for the backend's provoking vertex: the last on WebGL2, the first on WebGPU.
      const provoking = c.renderer === 'webgpu' ? 'first' : 'last';
      return row(
        c,
        { shading: 'flat' },
        { geometry: flatShadingGeometry(base, { provokingVertex: provoking }) },
      );
    }
    if (kind === 'gouraud') return row(c, { shading: 'gouraud' });
    return row(c, { celBands: 4, lighting: 'blinn-phong' });
  });
}
registerScene('doubleSide', (c) => {
  const geometry = new c.THREE.SphereGeometry(1.1, 48, 24, 0, Math.PI * 2, 0, Math.PI * 0.6);
  return row(c, {}, { geometry, material: (m) => (m.side = c.THREE.DoubleSide) });
});
registerScene('instanced', (c) => {
  const { THREE } = c;
  const setup = row(c, {});
  const mesh = setup.scene.children.find((o) => (o as InstanceType<Three['Mesh']>).isMesh) as InstanceType<
    Three['Mesh']
  >;
  const instanced = new THREE.InstancedMesh(
    new THREE.SphereGeometry(0.5, 32, 16),
    mesh.material as Material,
    3,
  );
  const m = new THREE.Matrix4();
  [-1.1, 0, 1.1].forEach((x, i) => {
    instanced.setMatrixAt(
      i,
      m.compose(new THREE.Vector3(x, 0, 0), new THREE.Quaternion(), new THREE.Vector3(1, 1.4 - 0.4 * i, 1)),
    );
    instanced.setColorAt(i, new THREE.Color().setHSL(i / 3, 0.7, 0.6));
  });
  setup.scene.remove(mesh);
  setup.scene.add(instanced);
  return setup;
});
registerScene('instancedSphere', (c) => {
  // The lecture's sphere without a normal attribute (its normal is its position), instanced with non-uniform
  // scales: each instance's normal turned by its own matrix.
  const { THREE } = c;
  const setup = row(c, {});
  const mesh = setup.scene.children.find((o) => (o as InstanceType<Three['Mesh']>).isMesh) as InstanceType<
    Three['Mesh']
  >;
  const geometry = new SubdivisionSphereGeometry({ level: 4, normals: 'none' });
  const instanced = new THREE.InstancedMesh(geometry, mesh.material as Material, 3);
  const m = new THREE.Matrix4();
  [-1.1, 0, 1.1].forEach((x, i) => {
    const scale = new THREE.Vector3(0.5, 0.7 - 0.2 * i, 0.5);
    instanced.setMatrixAt(i, m.compose(new THREE.Vector3(x, 0, 0), new THREE.Quaternion(), scale));
  });
  setup.scene.remove(mesh);
  setup.scene.add(instanced);
  return setup;
});
registerScene('shadows', (c) => {
  const { THREE } = c;
  const scene = new THREE.Scene();
  const light = new THREE.DirectionalLight(0xffffff, 3);
  light.position.set(-2, 4, 3);
  light.castShadow = true;
  light.shadow.mapSize.set(512, 512);
  Object.assign(light.shadow.camera, { left: -3, right: 3, top: 3, bottom: -3, near: 0.5, far: 12 });
  scene.add(light, light.target, new THREE.AmbientLight(0xffffff, 0.5));
  const ball = new THREE.Mesh(
    new THREE.SphereGeometry(0.7, 32, 16),
    shading(c, { ka: 0.6, kd: 0.6, ks: 0.3 }),
  );
  ball.position.set(0, 0.3, 0);
  ball.castShadow = true;
  const ground = new THREE.Mesh(new THREE.PlaneGeometry(6, 6), shading(c, { ka: 0.8, kd: 0.8, ks: 0 }));
  ground.rotation.x = -Math.PI / 2;
  ground.position.y = -0.6;
  ground.receiveShadow = true;
  scene.add(ball, ground);
  const view = camera(THREE, c, 4);
  view.position.set(0, 2, 4);
  view.lookAt(0, 0, 0);
  return { scene, camera: view, clearColor: 0x101820 };
});
