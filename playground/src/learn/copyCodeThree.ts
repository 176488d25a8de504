/**
 * Copy as code: the playground's scene as a plain three.js program (TypeScript) on the `@shadelab/*` packages,
 * the `src/main.ts` of a Vite app. Minimal: each option that equals the package's default is left out
 * (`copyCodeModel.ts`), and nothing of the playground is imported.
 */
import type { PlaygroundState } from '../state/schema';
import { args, Imports, literal, num, numbers, objectLiteral } from './copyCodeFormat';
import { type CodeScene, codeScene } from './copyCodeModel';
import { MODEL_URL, sceneCode } from './copyCodeScenes';

/**
 * Whether the `@shadelab/*` packages are on the npm registry. Until they are, a program installs them as the
 * README's Install does: from the tarballs that `npm run pack -- --out /tmp/shadelab` writes in a clone.
 */
export const PACKAGES_ON_NPM = false;

/** Where the README's Install has `npm run pack` write the tarballs. */
export const TARBALL_FOLDER = '/tmp/shadelab';

/**
 * The `@shadelab/*` packages each package depends on or has as a peer (its package.json). From tarballs, npm
 * would look for these on the registry, so they are installed from the tarballs beside it.
 */
export const SHADELAB_DEPENDENCIES: Readonly<Record<string, readonly string[]>> = {
  '@shadelab/material': ['@shadelab/sphere'],
  '@shadelab/playwright': ['@shadelab/material', '@shadelab/reference'],
  '@shadelab/react': ['@shadelab/camera', '@shadelab/material', '@shadelab/sphere', '@shadelab/trackball'],
  '@shadelab/reference': ['@shadelab/material'],
};

/**
 * The first lines of a generated program: how to install the packages its imports name (`three` always: it is
 * every package's peer) and the type packages `dev` (as dev dependencies), as the README says.
 */
export function installLine(imports: string, dev: readonly string[]): string {
  const packages = new Set<string>(['three']);
  for (const [, module] of imports.matchAll(/from '([^']+)'/g)) {
    const parts = module!.split('/');
    packages.add(module!.startsWith('@') ? parts.slice(0, 2).join('/') : parts[0]!);
  }
  for (const name of packages)
    for (const dependency of SHADELAB_DEPENDENCIES[name] ?? []) packages.add(dependency);
  const ours = [...packages].filter((p) => p.startsWith('@shadelab/')).sort();
  const others = [...packages].filter((p) => !p.startsWith('@shadelab/')).sort();
  const install = `npm install ${[...others, ...tarballs(ours)].join(' ')} && npm install --save-dev ${dev.join(' ')}`;
  if (PACKAGES_ON_NPM) return `// ${install}`;
  return [
    `// The @shadelab packages are not on npm yet: in a clone of shadelab, \`npm ci && npm run pack -- --out ${TARBALL_FOLDER}\`, then`,
    `// ${install}`,
  ].join('\n');
}

/** `ours` (`@shadelab/<name>`) as install arguments: the registry names, or today a glob over the tarballs. */
function tarballs(ours: readonly string[]): string[] {
  if (PACKAGES_ON_NPM || ours.length === 0) return [...ours];
  const names = ours.map((p) => p.slice('@shadelab/'.length));
  const name = names.length === 1 ? names[0] : `{${names.join(',')}}`;
  return [`${TARBALL_FOLDER}/shadelab-${name}-*.tgz`];
}

/** The camera lines: placed with the lecture's lookAt, then its projection for the window's aspect. */
export function cameraLines(camera: CodeScene['camera'], aspect: string): string[] {
  const lines = [`camera.lookAt(${numbers(camera.eye)}, ${numbers(camera.at)}, ${numbers(camera.up)});`];
  if (camera.projection === 'perspective') {
    lines.push(
      `camera.setPerspective(${[camera.fovy, aspect, camera.near, camera.far].map((v) => (typeof v === 'number' ? num(v) : v)).join(', ')});`,
    );
    return lines;
  }
  if (camera.zoom !== null) lines.push(`camera.zoom = ${num(camera.zoom)};`);
  const box = [...camera.box, camera.near, camera.far].map(num).join(', ');
  // setAspect keeps the box's height and middle and fits its width to the canvas.
  lines.push(`camera.setOrthographic(${box})${camera.fitAspect ? `.setAspect(${aspect})` : ''};`);
  return lines;
}

/** The TypeScript program that draws `state`'s scene with WebGLRenderer (a Vite app's `src/main.ts`). */
export function threeProgram(state: PlaygroundState): string {
  const code = codeScene(state);
  const imports = new Imports();
  imports.add('three', '* as THREE');
  const camera = imports.add('@shadelab/camera', 'Camera');
  const trackballClass = imports.add('@shadelab/trackball', 'Trackball');
  const top: string[] = [];
  const body: string[] = [];

  const parameters = code.depth
    ? `{ ...${imports.add('@shadelab/camera', 'depthBufferParameters')}(${literal(code.depth)}) }`
    : '';
  body.push(
    `const renderer = new THREE.WebGLRenderer(${parameters});`,
    'renderer.setSize(innerWidth, innerHeight);',
    'document.body.append(renderer.domElement);',
    'const scene = new THREE.Scene();',
    '',
    `const camera = new ${camera}();`,
    ...cameraLines(code.camera, 'innerWidth / innerHeight'),
  );

  code.lights.forEach(({ options, position }, i) => {
    const name = code.lights.length === 1 ? 'light' : `light${i + 1}`;
    imports.add('@shadelab/material', 'PhongLight');
    body.push('', `const ${name} = new PhongLight(${args(options)});`);
    if (position) body.push(`${name}.position.set(${position.map(num).join(', ')});`);
    body.push(`scene.add(${name});`);
  });
  body.push('');

  const { object, material, outline } = code;
  const materialOf = (cls: string) => `new ${cls}(${args(material)})`;
  let target = 'sphere';
  let afterLoad = false;
  if (object.kind === 'scene') {
    const scene = sceneCode(imports, object.name, { flat: object.flat, outline, swap: material });
    top.push(scene.declaration);
    if (scene.fog) {
      const { color, near, far } = scene.fog;
      body.push(
        `scene.fog = new THREE.Fog(${color}, ${num(near)}, ${num(far)});`,
        `scene.background = new THREE.Color(${color});`,
      );
    }
    if (scene.clipping) body.push('renderer.localClippingEnabled = true;');
    if (scene.world) body.push(`scene.add(${scene.world});`);
    if (object.name === 'model') {
      target = 'model';
      afterLoad = true;
      imports.add('three/addons/loaders/GLTFLoader.js', 'GLTFLoader');
      body.push(
        'const render = () => renderer.render(scene, camera);',
        `// Your model's URL (a .glb, or a .gltf):`,
        `new GLTFLoader().load(${literal(MODEL_URL)}, (gltf) => {`,
        `  const model = ${scene.build('')};`,
      );
    } else {
      target = 'object';
      imports.add('@shadelab/material', 'ShadingMaterial');
      body.push(`const object = ${scene.build(materialOf('ShadingMaterial'))};`);
    }
  } else if (object.kind === 'impostor') {
    imports.add('@shadelab/material/impostor', 'SphereImpostor', 'SphereImpostorMaterial');
    body.push(`const sphere = new SphereImpostor(${materialOf('SphereImpostorMaterial')});`);
  } else {
    imports.add('@shadelab/material', 'ShadingMaterial');
    body.push(`const material = ${materialOf('ShadingMaterial')};`);
    if (object.kind === 'auto') {
      imports.add('@shadelab/sphere/detail', 'AutoDetailSphere');
      const options = Object.keys(object.options).length ? `, ${objectLiteral(object.options)}` : '';
      body.push(`const sphere = new AutoDetailSphere(material${options});`);
    } else {
      imports.add('@shadelab/sphere', 'SubdivisionSphereGeometry');
      let geometry = `new SubdivisionSphereGeometry(${objectLiteral(object.geometry)})`;
      if (object.flat) {
        // Flat shading: each face lit once, at its centroid.
        geometry = `${imports.add('@shadelab/material', 'flatShadingGeometry')}(${geometry})`;
      }
      body.push(`const sphere = new THREE.Mesh(${geometry}, material);`);
    }
    if (outline) {
      imports.add('@shadelab/material/outline', 'createOutline');
      body.push(`createOutline(sphere${args(outline) ? `, ${args(outline)}` : ''});`);
    }
  }

  const indent = afterLoad ? '  ' : '';
  const tail: string[] = [];
  if (code.scale) tail.push(`${target}.scale.set(${code.scale.map(num).join(', ')});`);
  if (code.rotation) tail.push(`${target}.quaternion.set(${code.rotation.map(num).join(', ')});`);
  tail.push(`scene.add(${target});`, '');
  const trackballOptions = [
    'camera',
    ...Object.entries(code.trackball).map(([k, v]) => `${k}: ${literal(v)}`),
  ];
  tail.push(
    `const trackball = new ${trackballClass}(${target}, renderer.domElement, { ${trackballOptions.join(', ')} });`,
  );
  const render =
    object.kind === 'auto'
      ? '() => {\n  sphere.update(camera, renderer); // the detail for this frame\n  renderer.render(scene, camera);\n}'
      : '() => renderer.render(scene, camera)';
  if (!afterLoad) tail.push(`const render = ${render};`);
  if (code.damping) {
    // A fling keeps turning: the trackball steps its spin every frame.
    tail.push('renderer.setAnimationLoop(() => {', '  trackball.update();', '  render();', '});');
  } else {
    tail.push("trackball.addEventListener('change', render);", 'render();');
  }
  body.push(...tail.map((line) => (line ? indent + line.replace(/\n/g, `\n${indent}`) : line)));
  if (afterLoad) body.push('});');

  const head = imports.toString();
  return `${installLine(head, ['@types/three'])}\n${head}\n\n${top.map((d) => `${d}\n\n`).join('')}${body.join('\n').replace(/\n{3,}/g, '\n\n')}\n`;
}
