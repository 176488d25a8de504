import { useThree } from '@react-three/fiber';
import { Camera, type CameraOptions, type Vec3Input } from '@shadelab/camera';
import { type ReactNode, type Ref, useImperativeHandle, useLayoutEffect, useMemo } from 'react';

/** Props of {@link LectureCamera}. */
export interface LectureCameraProps extends CameraOptions {
  /** Make it R3F's default camera (the one R3F renders and raycasts with), restored on unmount. @default false */
  makeDefault?: boolean;
  /** Eye position, world units (the lecture's `lookAt(eye, at, up)`). @default [0, 0, 3] */
  eye?: Vec3Input;
  /** The point looked at, world units. @default [0, 0, 0] */
  at?: Vec3Input;
  /** The up direction (not parallel to the gaze). @default [0, 1, 0] */
  up?: Vec3Input;
  /** Children move with the camera (a headlight `<phongLight>`, for example). */
  children?: ReactNode;
  /** Receives the `Camera` instance. */
  ref?: Ref<Camera>;
}

/**
 * The lecture's `Camera` (`@shadelab/camera`) in R3F: a perspective camera placed with `lookAt(eye, at, up)`,
 * whose aspect follows the canvas (`setAspect` on every size change; R3F leaves it alone: `manual`), and with
 * `makeDefault` R3F's default camera. Bad values throw the camera's `RangeError` naming them. For an
 * orthographic projection, call `setOrthographic` on the instance (`ref`); the aspect still follows the canvas.
 *
 * @example
 * <LectureCamera makeDefault eye={[0, 0, 3]} fovy={90} near={0.1} far={10} />
 */
export function LectureCamera({
  makeDefault = false,
  eye = [0, 0, 3],
  at = [0, 0, 0],
  up = [0, 1, 0],
  fovy = 50,
  near = 0.1,
  far = 2000,
  children,
  ref,
}: LectureCameraProps) {
  const set = useThree((state) => state.set);
  const get = useThree((state) => state.get);
  const size = useThree((state) => state.size);
  const invalidate = useThree((state) => state.invalidate);
  const camera = useMemo(() => {
    const c = new Camera();
    // Ours to size: R3F's own resize would treat an orthographic lecture camera as three's.
    (c as Camera & { manual?: boolean }).manual = true;
    return c;
  }, []);
  useImperativeHandle(ref, () => camera, [camera]);

  const [ex, ey, ez] = toArray(eye);
  const [ax, ay, az] = toArray(at);
  const [ux, uy, uz] = toArray(up);
  useLayoutEffect(() => {
    camera.lookAt([ex, ey, ez], [ax, ay, az], [ux, uy, uz]);
    invalidate();
  }, [camera, ex, ey, ez, ax, ay, az, ux, uy, uz, invalidate]);

  const aspect = size.width / size.height;
  useLayoutEffect(() => {
    if (camera.isOrthographicCamera) {
      if (aspect > 0 && Number.isFinite(aspect)) camera.setAspect(aspect);
    } else {
      camera.setPerspective(fovy, aspect > 0 && Number.isFinite(aspect) ? aspect : 1, near, far);
    }
    invalidate();
  }, [camera, fovy, near, far, aspect, invalidate]);

  useLayoutEffect(() => {
    if (!makeDefault) return;
    const previous = get().camera;
    // R3F's store types its camera as three's PerspectiveCamera | OrthographicCamera; the lecture Camera
    // renders, raycasts (isPerspectiveCamera / isOrthographicCamera follow its projection) and is sized by us.
    set({ camera: camera as never });
    return () => {
      if (get().camera === (camera as unknown)) set({ camera: previous });
    };
  }, [makeDefault, camera, get, set]);

  return <primitive object={camera}>{children}</primitive>;
}

function toArray(v: Vec3Input): [number, number, number] {
  if ('x' in v) return [v.x, v.y, v.z];
  const a = v as ArrayLike<number>;
  return [a[0], a[1], a[2]];
}
