import { arcRotation, projectToBall, type Quat, Trackball } from '@shadelab/trackball';
import { Group, Matrix4, Mesh, PerspectiveCamera, Quaternion, Vector3 } from 'three';
import { describe, expect, it, vi } from 'vitest';

/** Largest deviation of the rotation matrix of q from orthonormal with det +1 (three.js builds the matrix). */
function orthonormalError(q: Quat): number {
  const e = new Matrix4().makeRotationFromQuaternion(new Quaternion(...q)).elements;
  const col = (j: number) => [e[4 * j], e[4 * j + 1], e[4 * j + 2]];
  const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const [u, v, w] = [col(0), col(1), col(2)];
  const det = new Matrix4().makeRotationFromQuaternion(new Quaternion(...q)).determinant();
  return Math.max(
    Math.abs(dot(u, u) - 1),
    Math.abs(dot(v, v) - 1),
    Math.abs(dot(w, w) - 1),
    Math.abs(dot(u, v)),
    Math.abs(dot(v, w)),
    Math.abs(dot(w, u)),
    Math.abs(det - 1),
  );
}

/** Small deterministic PRNG (mulberry32), so a failure can be replayed. */
function random(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Pointer coordinates that hit the centre, the rim, just inside/outside it, far outside, or anywhere. */
function pointerPicker(rand: () => number): () => [number, number] {
  return () => {
    const kind = Math.floor(rand() * 6);
    const angle = rand() * 2 * Math.PI;
    const r =
      kind === 0
        ? 0
        : kind === 1
          ? 1
          : kind === 2
            ? Math.SQRT1_2
            : kind === 3
              ? 1 + (rand() - 0.5) * 1e-9
              : kind === 4
                ? 10 ** (rand() * 12)
                : rand() * 3;
    return [r * Math.cos(angle), r * Math.sin(angle)];
  };
}

/**
 * A stand-in for the canvas and its document, as bench/trackball.bench.mjs uses: it keeps the listeners the
 * Trackball adds so that a test can call them directly (no DOM dispatch: 10⁶ drags take seconds, not minutes).
 */
function fakeElement(size: number) {
  const onElement = new Map<string, (event: unknown) => void>();
  const onDocument = new Map<string, (event: unknown) => void>();
  const listen = (map: typeof onElement) => ({
    addEventListener: (type: string, fn: (event: unknown) => void) => void map.set(type, fn),
    removeEventListener: (type: string) => void map.delete(type),
  });
  const element = {
    ...listen(onElement),
    ownerDocument: listen(onDocument),
    style: {},
    getBoundingClientRect: () => ({ left: 0, top: 0, width: size, height: size }),
    setPointerCapture() {},
    releasePointerCapture() {},
    hasPointerCapture: () => true,
  };
  return { element: element as unknown as HTMLElement, onElement, onDocument };
}

describe('trackball extremes (docs/design.md): 10⁶ drags through Trackball', () => {
  // 10⁶ drags fill half the default timeout under the gate's load: the timeout keeps four times their time.
  it('keeps the rotation and the object orthonormal within 1e-6 and never NaN over 10⁶ random drags', {
    timeout: 240_000,
  }, () => {
    const rand = random(20261123);
    const pick = pointerPicker(rand);
    const SIZE = 500; // ball radius 250 px, centre (250, 250)
    const { element, onElement, onDocument } = fakeElement(SIZE);
    // The object sits in a turned parent, and the camera turns now and then, so every conjugation is used.
    const parent = new Group();
    parent.quaternion.setFromAxisAngle(new Vector3(1, 2, -1).normalize(), 0.8);
    const mesh = new Mesh();
    parent.add(mesh);
    parent.updateMatrixWorld();
    const camera = new PerspectiveCamera();
    const tb = new Trackball(mesh, element, { camera, enableDamping: true });
    // The clock stands still: every release is a fling (within 100 ms of its last move) on any machine.
    const now = vi.spyOn(performance, 'now').mockReturnValue(0);
    const event = { pointerId: 1, pointerType: 'mouse', button: 0, clientX: 0, clientY: 0 };
    const at = ([x, y]: [number, number]) => {
      event.clientX = 250 + 250 * x;
      event.clientY = 250 - 250 * y;
      return event;
    };
    const q = (v: Quaternion): Quat => [v.x, v.y, v.z, v.w];
    let nonFinite = 0;
    let worst = 0;
    let checks = 0;
    const check = () => {
      worst = Math.max(worst, orthonormalError(q(tb.rotation)), orthonormalError(q(mesh.quaternion)));
      checks++;
    };
    for (let i = 0; i < 1_000_000; i++) {
      if (i % 10_000 === 0) {
        camera.position.set(rand() - 0.5, rand() - 0.5, rand() - 0.5).setLength(5);
        camera.lookAt(0, 0, 0);
        camera.updateMatrixWorld();
      }
      tb.mapping = i & 1 ? 'arcball' : 'bell';
      tb.rotateSpeed = (i % 5) * 0.75;
      const start = pick();
      onElement.get('pointerdown')?.(at(start));
      // One drag in eight has zero length; one in four has a second move.
      onDocument.get('pointermove')?.(at((i & 7) === 0 ? start : pick()));
      if ((i & 3) === 1) onDocument.get('pointermove')?.(at(pick()));
      onDocument.get('pointerup')?.(event);
      if ((i & 15) === 2) tb.update(); // the damped spin of a fling
      const r = tb.rotation;
      const o = mesh.quaternion;
      if (!Number.isFinite(r.x + r.y + r.z + r.w + o.x + o.y + o.z + o.w)) nonFinite++;
      if (i % 1000 === 999) check();
    }
    check();
    expect(checks).toBe(1001);
    expect(nonFinite).toBe(0);
    expect(worst).toBeLessThan(1e-6);
    expect(new Matrix4().makeRotationFromQuaternion(mesh.quaternion).elements.every(Number.isFinite)).toBe(
      true,
    );
    expect(tb.getWorldMatrix().elements.every(Number.isFinite)).toBe(true);
    expect(tb.dragging).toBe(false);
    tb.dispose();
    now.mockRestore();
    expect(onElement.size + onDocument.size).toBe(0);
  });
});

describe('trackball extremes (docs/design.md): the pure rotation core', () => {
  it.each(['arcball', 'bell'] as const)(
    '%s: centre, rim, beyond the rim and zero-length drags give finite unit rotations',
    (mapping) => {
      const points: [number, number][] = [
        [0, 0],
        [1, 0],
        [0, -1],
        [Math.SQRT1_2, Math.SQRT1_2],
        [Math.SQRT1_2, 0],
        [1 + 1e-15, 0],
        [1 - 1e-15, 0],
        [2, 2],
        [-1e9, 3],
        [1e300, -1e300],
        [Number.MIN_VALUE, 0],
      ];
      for (const [x0, y0] of points) {
        for (const [x1, y1] of points) {
          const q = arcRotation(projectToBall(x0, y0, mapping), projectToBall(x1, y1, mapping));
          expect(q.every(Number.isFinite)).toBe(true);
          expect(Math.abs(Math.hypot(...q) - 1)).toBeLessThan(1e-15);
          expect(orthonormalError(q)).toBeLessThan(1e-12);
          if (x0 === x1 && y0 === y1) expect(q).toEqual([0, 0, 0, 1]);
        }
      }
    },
  );
});
