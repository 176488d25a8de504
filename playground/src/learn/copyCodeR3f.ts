/**
 * Copy as code: the playground's scene as a React Three Fiber app (TSX) with `@shadelab/react`, the
 * `src/main.tsx` of a Vite app whose `index.html` has a `<div id="root">` sized by its CSS. The same scene as
 * `copyCodeThree.ts`'s program: the same minimal options (`copyCodeModel.ts`), written as JSX props.
 */
import type { PlaygroundState } from '../state/schema';
import { args, attributes, Imports, literal, num, numbers, objectLiteral } from './copyCodeFormat';
import { codeScene, type Options } from './copyCodeModel';
import { MODEL_URL, sceneCode } from './copyCodeScenes';
import { installLine } from './copyCodeThree';

/** `<LectureCamera>`'s own defaults (`@shadelab/react`): props equal to them are left out. */
export const LECTURE_CAMERA_DEFAULTS = {
  eye: [0, 0, 3],
  at: [0, 0, 0],
  up: [0, 1, 0],
  fovy: 50,
  near: 0.1,
  far: 2000,
} as const;

const differs = (a: number | readonly number[], b: number | readonly number[]) =>
  Array.isArray(a) ? (a as number[]).some((v, i) => v !== (b as readonly number[])[i]) : a !== b;

/** The TSX app that draws `state`'s scene with R3F's `<Canvas>` and `@shadelab/react`. */
export function r3fProgram(state: PlaygroundState): string {
  const code = codeScene(state);
  const imports = new Imports();
  imports.add('@react-three/fiber', 'Canvas');
  imports.add('react', 'StrictMode');
  imports.add('react-dom/client', 'createRoot');
  imports.add('@shadelab/react', 'LectureCamera', 'Trackball');
  const hooks: string[] = [];
  const jsx: string[] = [];
  const top: string[] = [];
  let background = "'#000000'";
  let fog = '';
  let clipping = false;
  let suspense = false;
  const memo = (name: string, value: string, deps = '[]') => {
    imports.add('react', 'useMemo');
    hooks.push(`const ${name} = useMemo(() => ${value}, ${deps});`);
  };

  // The camera: placed with the lecture's lookAt; an orthographic box set on the instance (its width then
  // follows the canvas's aspect).
  const c = code.camera;
  const cameraProps: Options = {};
  for (const key of ['eye', 'at', 'up'] as const) {
    if (differs(c[key], LECTURE_CAMERA_DEFAULTS[key])) cameraProps[key] = c[key];
  }
  let cameraRef = '';
  if (c.projection === 'perspective') {
    for (const key of ['fovy', 'near', 'far'] as const) {
      if (differs(c[key], LECTURE_CAMERA_DEFAULTS[key])) cameraProps[key] = c[key];
    }
  } else {
    const box = [...c.box, c.near, c.far].map(num).join(', ');
    const set = [
      ...(c.zoom === null ? [] : [`camera.zoom = ${num(c.zoom)};`]),
      `camera.setOrthographic(${box});`,
    ];
    cameraRef = ` ref={(camera) => {\n  if (camera) {\n    ${set.join('\n    ')}\n  }\n}}`;
    if (!c.fitAspect) jsx.push("{/* LectureCamera fits the box's width to the canvas's aspect. */}");
  }
  jsx.push(`<LectureCamera makeDefault${attributes(cameraProps)}${cameraRef} />`);

  for (const { options, position } of code.lights) {
    // Constructor options (a number is a grey level there; R3F's colour props read a number as hex).
    const light = Object.keys(options).length ? ` args={[${objectLiteral(options)}]}` : '';
    jsx.push(`<phongLight${light}${position ? ` position={${numbers(position)}}` : ''} />`);
  }

  const { object, material, outline } = code;
  const placed = `${code.scale ? ` scale={${numbers(code.scale)}}` : ''}${code.rotation ? ` quaternion={${numbers(code.rotation)}}` : ''}`;
  const turned: string[] = [];
  const materialElement = `<shadingMaterial${attributes(material)} />`;
  if (object.kind === 'scene' && object.name === 'model') {
    suspense = true;
    imports.add('@react-three/fiber', 'useLoader');
    imports.add('three/addons/loaders/GLTFLoader.js', 'GLTFLoader');
    imports.add('three', '* as THREE');
    imports.add('@shadelab/react', 'ShadedModel');
    hooks.push(
      `// Your model's URL (a .glb, or a .gltf):`,
      `const gltf = useLoader(GLTFLoader, ${literal(MODEL_URL)});`,
    );
    memo(
      'bounds',
      'new THREE.Box3().setFromObject(gltf.scene).getBoundingSphere(new THREE.Sphere())',
      '[gltf]',
    );
    hooks.push(
      '// Framed: its bounding sphere at the origin, radius 1.5.',
      'const scale = 1.5 / bounds.radius;',
    );
    if (outline) {
      imports.add('react', 'useLayoutEffect');
      imports.add('@shadelab/material/outline', 'createOutline');
      hooks.push(
        'useLayoutEffect(() => {',
        '  const meshes: THREE.Mesh[] = [];',
        '  gltf.scene.traverse((object) => {',
        '    if (object instanceof THREE.Mesh) meshes.push(object);',
        '  });',
        `  const outlines = meshes.map((mesh) => createOutline(mesh${args(outline) ? `, ${args(outline)}` : ''}));`,
        '  return () => {',
        '    for (const o of outlines) o.removeFromParent();',
        '  };',
        '}, [gltf]);',
      );
    }
    // three's lights for the model, in world space (the trackball turns the model only).
    jsx.push(
      '<hemisphereLight args={[0xffffff, 0x333333, 0.8]} />',
      '<directionalLight args={[0xffffff, 1.8]} position={[2, 3, 4]} />',
      '<directionalLight args={[0xffffff, 0.5]} position={[-4, 0, 3]} />',
    );
    const at = 'position={bounds.center.clone().multiplyScalar(-scale)}';
    const group = code.rotation
      ? [`<group quaternion={${numbers(code.rotation)}}>`, '  ', '</group>']
      : ['', '', ''];
    if (group[0]) turned.push(group[0]);
    turned.push(`${group[1]}<ShadedModel object={gltf.scene} scale={scale} ${at}${attributes(material)} />`);
    if (group[2]) turned.push(group[2]);
  } else if (object.kind === 'scene') {
    imports.add('@shadelab/material', 'ShadingMaterial');
    const scene = sceneCode(imports, object.name, { flat: object.flat, outline, swap: material });
    if (/THREE\./.test(scene.declaration)) imports.add('three', '* as THREE');
    top.push(scene.declaration);
    memo('object', scene.build(`new ShadingMaterial(${args(material)})`));
    if (scene.fog) {
      background = scene.fog.color;
      fog = `<fog attach="fog" args={[${scene.fog.color}, ${num(scene.fog.near)}, ${num(scene.fog.far)}]} />`;
    }
    clipping = scene.clipping === true;
    turned.push(`<primitive object={object}${placed} />`);
  } else if (object.kind === 'impostor') {
    imports.add('@shadelab/material/impostor', 'SphereImpostorMaterial');
    memo('impostor', `new SphereImpostorMaterial(${args(material)})`);
    turned.push(`<sphereImpostor args={[impostor]}${placed} />`);
  } else if (object.kind === 'auto') {
    imports.add('@shadelab/react', 'AutoDetailSphere');
    turned.push(
      `<AutoDetailSphere${attributes(object.options)}${placed}>`,
      `  ${materialElement}`,
      '</AutoDetailSphere>',
    );
  } else if (!object.flat && !outline) {
    turned.push(
      `<mesh${placed}>`,
      `  <subdivisionSphereGeometry args={[${objectLiteral(object.geometry)}]} />`,
      `  ${materialElement}`,
      '</mesh>',
    );
  } else {
    // One geometry for the sphere and its outline; flat shading lights each face once, at its centroid.
    imports.add('@shadelab/sphere', 'SubdivisionSphereGeometry');
    let geometry = `new SubdivisionSphereGeometry(${objectLiteral(object.geometry)})`;
    if (object.flat) geometry = `${imports.add('@shadelab/material', 'flatShadingGeometry')}(${geometry})`;
    memo('geometry', geometry);
    turned.push(`<mesh geometry={geometry}${placed}>`, `  ${materialElement}`, '</mesh>');
    if (outline) {
      turned.push(
        `<mesh geometry={geometry}${placed}>`,
        `  <outlineMaterial${attributes(outline)} />`,
        '</mesh>',
      );
    }
  }
  const trackball = `<Trackball${attributes(code.trackball)}>`;
  jsx.push(trackball, ...turned.map((line) => `  ${line}`), '</Trackball>');
  const canvasProps: string[] = ['flat', 'frameloop="demand"'];
  if (code.depth) {
    imports.add('@shadelab/camera', 'depthBufferParameters');
    canvasProps.push(`gl={{ ...depthBufferParameters(${literal(code.depth)}) }}`);
  }
  if (clipping) canvasProps.push('onCreated={({ gl }) => {\n      gl.localClippingEnabled = true;\n    }}');
  if (suspense) imports.add('react', 'Suspense');

  const scene = [`<color attach="background" args={[${background}]} />`, ...(fog ? [fog] : []), ...jsx];
  const head = imports.toString();
  const body = [
    'function Scene() {',
    ...hooks.map((line) => `  ${line}`),
    '  return (',
    '    <>',
    ...scene.map((line) => `      ${line.replace(/\n/g, '\n      ')}`),
    '    </>',
    '  );',
    '}',
    '',
    "const root = document.getElementById('root');",
    "if (!root) throw new Error('no #root element');",
    'createRoot(root).render(',
    '  <StrictMode>',
    `    <Canvas ${canvasProps.join(' ')}>`,
    suspense ? '      <Suspense fallback={null}>\n        <Scene />\n      </Suspense>' : '      <Scene />',
    '    </Canvas>',
    '  </StrictMode>,',
    ');',
  ];
  const install = installLine(head, ['@types/react', '@types/react-dom', '@types/three']);
  return `${install}\n${head}\n\n${top.map((d) => `${d}\n\n`).join('')}${body.join('\n')}\n`;
}
