// The trade-off scene shared by the trade-off page, its Playwright harness and its benchmark: one lit
// sphere (ellipsoid) drawn by one option (a subdivision mesh with flat, Gouraud or Phong shading, or the
// ray-cast impostor), and the exact reference image of the same view.
import {
  flatShadingGeometry,
  PhongLight,
  type ShadeLight,
  type ShadeMaterial,
  ShadingMaterial,
} from '@shadelab/material';
import { SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { type ReferenceImage, renderReference } from '@shadelab/reference';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import {
  type BufferGeometry,
  type Camera,
  Mesh,
  OrthographicCamera,
  PerspectiveCamera,
  Scene,
  WebGLRenderer,
} from 'three';
import { resolveView, type TradeOption, type TradeView } from './tradeOption';

// The harness, the bench and the tests import these from here, beside the scene that draws them.
export {
  type OptionCost,
  optionCost,
  optionKey,
  type TradeLight,
  type TradeOption,
  type TradeView,
} from './tradeOption';

/** The background: pure blue, a colour the shading never produces (so coverage is exact). */
export const BACKGROUND = 0x0000ff;

/** Renderer, scene and the objects of the trade, on one canvas. */
export class TradeoffScene {
  readonly renderer: WebGLRenderer;
  readonly scene = new Scene();
  /** The lights of the current view (`setView` adds or removes them). */
  lights: PhongLight[] = [new PhongLight()];
  camera: Camera = new PerspectiveCamera();
  readonly meshMaterial = new ShadingMaterial();
  readonly impostorMaterial = new SphereImpostorMaterial();
  readonly mesh = new Mesh<BufferGeometry, ShadingMaterial>(undefined, this.meshMaterial);
  readonly impostor = new SphereImpostor(this.impostorMaterial);
  view: Required<TradeView> = resolveView({ width: 1, height: 1 });
  option: TradeOption = { shading: 'impostor' };
  readonly #geometries = new Map<string, BufferGeometry>();
  #reference: { key: string; image: ReferenceImage } | null = null;

  /** @param depth - The renderer's depth buffer: three's `logarithmicDepthBuffer` / `reversedDepthBuffer`. */
  constructor(
    canvas: HTMLCanvasElement | OffscreenCanvas,
    depth: { logarithmicDepthBuffer?: boolean; reversedDepthBuffer?: boolean } = {},
  ) {
    this.renderer = new WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true, ...depth });
    this.renderer.setPixelRatio(1);
    this.renderer.setClearColor(BACKGROUND, 1);
    this.meshMaterial.phongLights = this.lights;
    this.impostorMaterial.phongLights = this.lights;
    this.scene.add(...this.lights, this.mesh, this.impostor);
  }

  /** Set the view (camera, model transform, light and material options). */
  setView(view: TradeView): void {
    const v = resolveView(view);
    this.view = v;
    if (this.renderer.domElement.width !== v.width || this.renderer.domElement.height !== v.height) {
      this.renderer.setSize(v.width, v.height, false);
    }
    const aspect = v.width / v.height;
    // The lecture's near 0.1 and far 10, pushed out when the eye is farther (zoomed out).
    const { near, far } = v;
    if (v.projection === 'orthographic') {
      const h = 1.5;
      this.camera = new OrthographicCamera(-h * aspect, h * aspect, h, -h, near, far);
    } else {
      this.camera = new PerspectiveCamera(v.fovy, aspect, near, far);
    }
    this.camera.position.set(...v.eye);
    this.camera.lookAt(0, 0, 0);
    this.camera.updateMatrixWorld();
    for (const object of [this.mesh, this.impostor]) {
      object.scale.set(...v.scale);
      object.rotation.set(...v.rotation);
    }
    if (this.lights.length !== v.lights.length) {
      this.scene.remove(...this.lights);
      this.lights = v.lights.map(() => new PhongLight());
      this.scene.add(...this.lights);
      this.meshMaterial.phongLights = this.lights;
      this.impostorMaterial.phongLights = this.lights;
    }
    v.lights.forEach((l, i) => {
      const light = this.lights[i];
      light.position.set(...l.position);
      light.ambient = l.ambient ?? [0.2, 0.2, 0.2];
      light.diffuse = l.diffuse ?? [1, 1, 1];
      light.specular = l.specular ?? [0.8, 0.8, 0.8];
      light.attenuation = { a: 1, b: 0, c: 0, ...l.attenuation };
    });
    this.scene.updateMatrixWorld();
    for (const m of [this.meshMaterial, this.impostorMaterial]) {
      m.lighting = v.lighting;
      m.celBands = v.celBands;
      m.shininess = v.shininess;
      m.ka = v.ka;
      m.kd = v.kd;
      m.ks = v.ks;
    }
  }

  /** Choose what draws the sphere. */
  setOption(option: TradeOption): void {
    this.option = option;
    const impostor = option.shading === 'impostor';
    this.impostor.visible = impostor;
    this.mesh.visible = !impostor;
    if (option.shading === 'impostor') return;
    this.meshMaterial.shading = option.shading;
    // Flat shading draws flatShadingGeometry of the indexed sphere (each face lit once, on a provoking
    // vertex of its own), as the library recommends; Gouraud and Phong the indexed sphere itself.
    const flat = option.shading === 'flat';
    const key = `${option.base}/${option.level}/${flat}`;
    let g = this.#geometries.get(key);
    if (g === undefined) {
      const sphere = new SubdivisionSphereGeometry({
        base: option.base,
        level: option.level,
        normals: 'none',
        indexed: true,
      });
      g = flat ? flatShadingGeometry(sphere) : sphere;
      if (flat) sphere.dispose();
      this.#geometries.set(key, g);
    }
    this.mesh.geometry = g;
  }

  render(): void {
    this.renderer.render(this.scene, this.camera);
  }

  /** The whole canvas, RGBA, rows bottom-up. */
  readPixels(): Uint8Array {
    const gl = this.renderer.getContext();
    const { width, height } = this.view;
    const pixels = new Uint8Array(4 * width * height);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    return pixels;
  }

  /** One pixel read back: waits for the frame (SwiftShader's finish() does not). */
  sync(): void {
    const gl = this.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
  }

  /** The exact image of the current view (cached until the view changes). */
  reference(samples = 4): ReferenceImage {
    const key = JSON.stringify([this.view, samples]);
    if (this.#reference?.key === key) return this.#reference.image;
    const object = this.impostor;
    object.updateMatrixWorld();
    const m = this.meshMaterial;
    const material: ShadeMaterial = {
      ka: [m.ka.r, m.ka.g, m.ka.b],
      kd: [m.kd.r, m.kd.g, m.kd.b],
      ks: [m.ks.r, m.ks.g, m.ks.b],
      shininess: m.shininess,
      lighting: m.lighting,
      celBands: m.celBands,
    };
    const lights: ShadeLight[] = this.lights.map((l) => {
      const e = l.matrixWorld.elements;
      return {
        position: [e[12], e[13], e[14]],
        ambient: [l.ambient.r, l.ambient.g, l.ambient.b],
        diffuse: [l.diffuse.r, l.diffuse.g, l.diffuse.b],
        specular: [l.specular.r, l.specular.g, l.specular.b],
        attenuation: l.attenuation,
      };
    });
    const image = renderReference({
      width: this.view.width,
      height: this.view.height,
      projectionMatrix: this.camera.projectionMatrix.elements,
      viewMatrix: this.camera.matrixWorldInverse.elements,
      modelMatrix: object.matrixWorld.elements,
      material,
      lights,
      background: [0, 0, 1],
      samples,
    });
    this.#reference = { key, image };
    return image;
  }

  dispose(): void {
    for (const g of this.#geometries.values()) g.dispose();
    this.impostor.geometry.dispose();
    this.meshMaterial.dispose();
    this.impostorMaterial.dispose();
    this.renderer.dispose();
  }
}
