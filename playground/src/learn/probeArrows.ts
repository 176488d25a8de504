/**
 * The probe's vectors drawn in 3D at the probed point: n, v, and each light's l and r (Phong lighting) or h
 * (Blinn-Phong), as labelled arrows (three's ArrowHelper and a text sprite), drawn over the surface (no depth
 * test) so that an l pointing below the horizon still shows.
 */
import * as THREE from 'three';
import type { ProbeHit } from './probePick';

/** One arrow: its label, unit direction (world) and colour. */
export interface ProbeArrow {
  readonly label: string;
  readonly direction: readonly [number, number, number];
  readonly color: number;
}

/** Arrow colours by vector (the panel's labels use the same). */
export const ARROW_COLORS = { n: 0xffffff, v: 0x55ddff, l: 0xffdd33, r: 0xff66cc, h: 0x66ff88 } as const;

/** The arrows of a probe: n and v, then l and r or h of each light that has an l. */
export function arrowsOf(hit: ProbeHit): ProbeArrow[] {
  const e = hit.explanation;
  const arrows: ProbeArrow[] = [
    { label: 'n', direction: e.n, color: ARROW_COLORS.n },
    { label: 'v', direction: e.v, color: ARROW_COLORS.v },
  ];
  const several = e.lights.length > 1;
  e.lights.forEach((light, i) => {
    if (!light.l) return;
    const suffix = several ? String(i + 1) : '';
    arrows.push({ label: `l${suffix}`, direction: light.l, color: ARROW_COLORS.l });
    if (light.r) arrows.push({ label: `r${suffix}`, direction: light.r, color: ARROW_COLORS.r });
    if (light.h?.some((c) => c !== 0))
      arrows.push({ label: `h${suffix}`, direction: light.h, color: ARROW_COLORS.h });
  });
  return arrows;
}

function labelSprite(text: string, color: number): THREE.Sprite {
  const canvas = document.createElement('canvas');
  canvas.width = 64;
  canvas.height = 32;
  const context = canvas.getContext('2d');
  if (context) {
    context.font = 'bold 24px ui-monospace, monospace';
    context.textBaseline = 'middle';
    context.fillStyle = `#${color.toString(16).padStart(6, '0')}`;
    context.fillText(text, 4, 16);
  }
  const texture = new THREE.CanvasTexture(canvas);
  texture.colorSpace = THREE.SRGBColorSpace;
  const material = new THREE.SpriteMaterial({ map: texture, depthTest: false, transparent: true });
  const sprite = new THREE.Sprite(material);
  sprite.renderOrder = 1001;
  return sprite;
}

/** The arrows' group in a scene: `show` puts a probe's arrows at its point, `clear` removes them. */
export class ProbeArrows {
  readonly group = new THREE.Group();

  constructor() {
    this.group.name = 'probe arrows';
  }

  /** Draws `arrows` from `origin` (world), each `length` world units long. */
  show(origin: readonly [number, number, number], arrows: readonly ProbeArrow[], length: number): void {
    this.clear();
    const at = new THREE.Vector3(...origin);
    for (const arrow of arrows) {
      const direction = new THREE.Vector3(...arrow.direction);
      if (!(direction.length() > 0)) continue;
      direction.normalize();
      const helper = new THREE.ArrowHelper(direction, at, length, arrow.color, 0.18 * length, 0.08 * length);
      helper.traverse((part) => {
        const drawn = part as THREE.Mesh | THREE.Line;
        if (!drawn.material) return;
        (drawn.material as THREE.Material).depthTest = false;
        drawn.renderOrder = 1000;
      });
      const label = labelSprite(arrow.label, arrow.color);
      label.position
        .copy(direction)
        .multiplyScalar(length * 1.15)
        .add(at);
      label.scale.set(0.3 * length, 0.15 * length, 1);
      this.group.add(helper, label);
    }
  }

  /** Removes the arrows and frees their geometries, materials and textures. */
  clear(): void {
    for (const child of [...this.group.children]) {
      if (child instanceof THREE.ArrowHelper) child.dispose();
      if (child instanceof THREE.Sprite) {
        child.material.map?.dispose();
        child.material.dispose();
      }
      this.group.remove(child);
    }
  }
}
