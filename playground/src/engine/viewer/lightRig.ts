/**
 * The scene's Phong lights, a marker on each, and the gizmo (three's TransformControls) that moves the selected
 * light's marker; the trackball and the movement keys pause while it drags.
 */
import { PhongLight } from '@shadelab/material';
import * as THREE from 'three';
import { TransformControls } from 'three/addons/controls/TransformControls.js';
import type { LightState } from '../../state/schema';
import { applyLight } from './applyState';
import type { ViewerEvents, ViewerHost } from './host';

export class LightRig {
  /** The lights, in the state's order. */
  readonly lights: PhongLight[] = [];
  /** Moves the selected light's marker. */
  readonly gizmo: TransformControls;
  private readonly markers: THREE.Mesh[] = [];
  private readonly markerGeometry = new THREE.SphereGeometry(0.08, 12, 8);
  private readonly markerMaterial = new THREE.MeshBasicMaterial({ color: 0xffee88 });
  /** The light the gizmo is on (0-based), or null. */
  private selected: number | null = null;

  /**
   * Listens on the canvas before the trackball is connected to it, so that grabbing a handle disables the
   * trackball before it sees the press.
   */
  constructor(
    private readonly host: ViewerHost,
    private readonly events: ViewerEvents,
  ) {
    this.gizmo = new TransformControls(host.camera, host.canvas);
    this.gizmo.setSize(0.8);
    this.gizmo.addEventListener('dragging-changed', this.onDragging);
    this.gizmo.addEventListener('change', this.onChange);
    this.gizmo.addEventListener('objectChange', this.onMove);
    this.gizmo.addEventListener('mouseUp', this.onDone);
    host.scene.add(this.gizmo.getHelper());
  }

  private readonly onDragging = (event: { value: unknown }) => {
    this.host.trackball.enabled = !event.value && !this.host.state?.camera.dragTurns;
    this.host.mover.enabled = !event.value;
  };
  private readonly onChange = () => this.host.requestRender();
  private readonly onMove = () => {
    const i = this.selected;
    if (i === null) return;
    this.lights[i]?.position.copy(this.markers[i]!.position);
    this.lights[i]?.updateMatrixWorld(true);
    this.host.requestRender();
  };
  private readonly onDone = () => {
    const i = this.selected;
    if (i === null || !this.markers[i]) return;
    const p = this.markers[i]!.position;
    this.events.onLightMoved?.(i, [p.x, p.y, p.z]);
  };

  /** Puts the gizmo on light `index` (0-based), or removes it (null). */
  select(index: number | null): void {
    this.selected = index !== null && this.markers[index] ? index : null;
    if (this.selected === null) this.gizmo.detach();
    else this.gizmo.attach(this.markers[this.selected]!);
    this.host.requestRender();
  }

  /** As many lights (and markers) as `states`, each set from its state. */
  apply(states: LightState[]): void {
    const { scene } = this.host;
    while (this.lights.length < states.length) {
      const light = new PhongLight();
      const marker = new THREE.Mesh(this.markerGeometry, this.markerMaterial);
      marker.name = `light marker ${this.lights.length + 1}`;
      scene.add(light, marker);
      this.lights.push(light);
      this.markers.push(marker);
    }
    while (this.lights.length > states.length) {
      const marker = this.markers.pop()!;
      if (this.gizmo.object === marker) this.select(null);
      scene.remove(this.lights.pop()!, marker);
    }
    states.forEach((s, i) => {
      applyLight(this.lights[i]!, s);
      this.markers[i]!.position.set(...s.position);
    });
  }

  dispose(): void {
    this.gizmo.removeEventListener('dragging-changed', this.onDragging);
    this.gizmo.removeEventListener('change', this.onChange);
    this.gizmo.removeEventListener('objectChange', this.onMove);
    this.gizmo.removeEventListener('mouseUp', this.onDone);
    this.gizmo.dispose();
    this.markerGeometry.dispose();
    this.markerMaterial.dispose();
  }
}
