/**
 * Temporary three.js stand-ins for the shadelab packages, used only until each package lands.
 * Everything here is reached through ./packages.ts, so switching to a real package is a one-file change.
 */
import * as THREE from 'three';
import type { Rgb, SphereBase, Vec3 } from '../state/schema';

// ---- sphere ------------------------------------------------------------------------------------------------

export function standInSphere(base: SphereBase, level: number): THREE.BufferGeometry {
  const detail = 2 ** level;
  if (base === 'octahedron') return new THREE.OctahedronGeometry(1, Math.min(detail, 64) - 1);
  if (base === 'icosahedron') return new THREE.IcosahedronGeometry(1, Math.min(detail, 64) - 1);
  return new THREE.TetrahedronGeometry(1, Math.min(detail, 64) - 1);
}

// ---- camera -------------------------------------------------------------------------------------------------

export class StandInCamera extends THREE.Camera {
  isOrthographic = false;
}

export class StandInMover extends THREE.EventDispatcher<{ change: object }> {
  speed = 0.1;
  private element: HTMLElement | null = null;
  constructor(private readonly camera: StandInCamera) {
    super();
  }
  private readonly onKey = (event: KeyboardEvent) => {
    const frame = new THREE.Matrix3().setFromMatrix4(this.camera.matrixWorld);
    const e = frame.elements;
    const u = new THREE.Vector3(e[0], e[1], e[2]);
    const v = new THREE.Vector3(e[3], e[4], e[5]);
    const w = new THREE.Vector3(e[6], e[7], e[8]);
    const move: Record<string, [THREE.Vector3, number]> = {
      w: [w, -1],
      s: [w, 1],
      a: [u, -1],
      d: [u, 1],
      r: [v, 1],
      f: [v, -1],
    };
    const hit = move[event.key.toLowerCase()];
    if (!hit) return;
    this.camera.position.addScaledVector(hit[0], hit[1] * this.speed);
    this.camera.updateMatrixWorld();
    this.dispatchEvent({ type: 'change' });
  };
  connect(element: HTMLElement) {
    this.element = element;
    element.addEventListener('keydown', this.onKey);
  }
  disconnect() {
    this.element?.removeEventListener('keydown', this.onKey);
    this.element = null;
  }
  dispose() {
    this.disconnect();
  }
}

// ---- trackball ----------------------------------------------------------------------------------------------

export class StandInTrackball extends THREE.EventDispatcher<{ change: object; start: object; end: object }> {
  rotateSpeed = 1;
  zoomSpeed = 1;
  enabled = true;
  private element: HTMLElement | null = null;
  private last: THREE.Vector3 | null = null;
  constructor(
    readonly object: THREE.Object3D,
    private readonly camera: THREE.Camera,
  ) {
    super();
  }
  private toBall(event: PointerEvent): THREE.Vector3 {
    const rect = this.element!.getBoundingClientRect();
    const r = Math.min(rect.width, rect.height) / 2;
    const x = (event.clientX - rect.left - rect.width / 2) / r;
    const y = -(event.clientY - rect.top - rect.height / 2) / r;
    const d = x * x + y * y;
    return new THREE.Vector3(x, y, d < 1 ? Math.sqrt(1 - d) : 0).normalize();
  }
  private readonly onDown = (event: PointerEvent) => {
    if (!this.enabled) return;
    this.last = this.toBall(event);
    this.element!.setPointerCapture?.(event.pointerId);
    this.dispatchEvent({ type: 'start' });
  };
  private readonly onMove = (event: PointerEvent) => {
    if (!this.last) return;
    const next = this.toBall(event);
    const axis = new THREE.Vector3().crossVectors(this.last, next);
    const angle = Math.atan2(axis.length(), this.last.dot(next)) * this.rotateSpeed;
    this.last = next;
    if (axis.lengthSq() === 0) return;
    axis.normalize().transformDirection(this.camera.matrixWorld);
    this.object.quaternion.premultiply(new THREE.Quaternion().setFromAxisAngle(axis, angle)).normalize();
    this.dispatchEvent({ type: 'change' });
  };
  private readonly onUp = () => {
    if (!this.last) return;
    this.last = null;
    this.dispatchEvent({ type: 'end' });
  };
  connect(element: HTMLElement) {
    this.element = element;
    element.addEventListener('pointerdown', this.onDown);
    element.addEventListener('pointermove', this.onMove);
    element.addEventListener('pointerup', this.onUp);
    element.addEventListener('pointercancel', this.onUp);
  }
  disconnect() {
    const element = this.element;
    if (!element) return;
    element.removeEventListener('pointerdown', this.onDown);
    element.removeEventListener('pointermove', this.onMove);
    element.removeEventListener('pointerup', this.onUp);
    element.removeEventListener('pointercancel', this.onUp);
    this.element = null;
  }
  dispose() {
    this.disconnect();
  }
}

// ---- material -----------------------------------------------------------------------------------------------

export class StandInLight extends THREE.Object3D {
  ambient = new THREE.Color(0.2, 0.2, 0.2);
  diffuse = new THREE.Color(1, 1, 1);
  specular = new THREE.Color(0.8, 0.8, 0.8);
  attenuation = { a: 1, b: 0, c: 0 };
}

const vertexShader = /* glsl */ `
struct Light { vec3 position; vec3 ambient; vec3 diffuse; vec3 specular; vec3 attenuation; };
uniform Light lights[NUM_LIGHTS];
uniform vec3 ka, kd, ks;
uniform float shininess;
out vec3 vWorld;
out vec3 vNormal;
out vec3 vColor;
vec3 shadePoint(vec3 p, vec3 n);
void main() {
  vec4 world = modelMatrix * vec4(position, 1.0);
  vWorld = world.xyz;
  vNormal = normalize(transpose(inverse(mat3(modelMatrix))) * position);
#if SHADING == 2
  vColor = shadePoint(vWorld, vNormal);
#endif
  gl_Position = projectionMatrix * viewMatrix * world;
}
vec3 shadePoint(vec3 p, vec3 n) {
  vec3 v = normalize(cameraPosition - p);
  vec3 sum = vec3(0.0);
  for (int i = 0; i < NUM_LIGHTS; i++) {
    vec3 l = normalize(lights[i].position - p);
    float ln = max(dot(l, n), 0.0);
    float spec = ln > 0.0 ? pow(max(dot(reflect(-l, n), v), 0.0), shininess) : 0.0;
    sum += ka * lights[i].ambient + kd * lights[i].diffuse * ln + ks * lights[i].specular * spec;
  }
  return sum;
}
`;

const fragmentShader = /* glsl */ `
struct Light { vec3 position; vec3 ambient; vec3 diffuse; vec3 specular; vec3 attenuation; };
uniform Light lights[NUM_LIGHTS];
uniform vec3 ka, kd, ks;
uniform float shininess;
in vec3 vWorld;
in vec3 vNormal;
in vec3 vColor;
vec3 shadePoint(vec3 p, vec3 n) {
  vec3 v = normalize(cameraPosition - p);
  vec3 sum = vec3(0.0);
  for (int i = 0; i < NUM_LIGHTS; i++) {
    vec3 l = normalize(lights[i].position - p);
    float ln = max(dot(l, n), 0.0);
#if CEL_BANDS > 0
    ln = floor(ln * float(CEL_BANDS)) / float(CEL_BANDS - 1);
#endif
#if BLINN
    float spec = ln > 0.0 ? pow(max(dot(normalize(l + v), n), 0.0), shininess) : 0.0;
#else
    float spec = ln > 0.0 ? pow(max(dot(reflect(-l, n), v), 0.0), shininess) : 0.0;
#endif
    sum += ka * lights[i].ambient + kd * lights[i].diffuse * ln + ks * lights[i].specular * spec;
  }
  return sum;
}
void main() {
#if SHADING == 1
  vec3 n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
  vec3 color = shadePoint(vWorld, n);
#elif SHADING == 2
  vec3 color = vColor;
#else
  vec3 color = shadePoint(vWorld, normalize(vNormal));
#endif
  gl_FragColor = vec4(color, 1.0);
  #include <colorspace_fragment>
}
`;

const SHADING_CODE = { flat: 1, gouraud: 2, phong: 3 } as const;

export class StandInMaterial extends THREE.ShaderMaterial {
  shading: keyof typeof SHADING_CODE = 'phong';
  lighting: 'phong' | 'blinn-phong' = 'phong';
  celBands = 0;
  phongLights: StandInLight[] = [];
  constructor() {
    super({
      vertexShader,
      fragmentShader,
      glslVersion: null,
      uniforms: {
        lights: { value: [] },
        ka: { value: new THREE.Color() },
        kd: { value: new THREE.Color() },
        ks: { value: new THREE.Color() },
        shininess: { value: 50 },
      },
    });
    this.syncDefines();
  }
  syncDefines() {
    const defines = {
      SHADING: SHADING_CODE[this.shading],
      BLINN: this.lighting === 'blinn-phong' ? 1 : 0,
      CEL_BANDS: this.celBands,
      NUM_LIGHTS: Math.max(1, this.phongLights.length),
    };
    if (JSON.stringify(defines) !== JSON.stringify(this.defines)) {
      this.defines = defines;
      this.needsUpdate = true;
    }
  }
  syncLights() {
    const p = new THREE.Vector3();
    const list = this.phongLights.length
      ? this.phongLights
      : [
          Object.assign(new StandInLight(), {
            ambient: new THREE.Color(0, 0, 0),
            diffuse: new THREE.Color(0, 0, 0),
          }),
        ];
    this.uniforms['lights']!.value = list.map((light) => ({
      position: light.getWorldPosition(p).clone(),
      ambient: light.ambient,
      diffuse: light.diffuse,
      specular: this.phongLights.length ? light.specular : new THREE.Color(0, 0, 0),
      attenuation: new THREE.Vector3(light.attenuation.a, light.attenuation.b, light.attenuation.c),
    }));
  }
  setColors(ka: Rgb, kd: Rgb, ks: Rgb, shininess: number) {
    (this.uniforms['ka']!.value as THREE.Color).setRGB(...ka);
    (this.uniforms['kd']!.value as THREE.Color).setRGB(...kd);
    (this.uniforms['ks']!.value as THREE.Color).setRGB(...ks);
    this.uniforms['shininess']!.value = shininess;
  }
}

export const vec = (v: Vec3) => new THREE.Vector3(...v);
