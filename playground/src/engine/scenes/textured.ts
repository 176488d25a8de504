/**
 * A textured model with a normal map: a torus knot with a colour map (a two-tone checker) and a tangent-space
 * normal map (rounded bumps), both made in code as DataTextures, so no download and the same texels on every
 * run. They are set as three's `map` and `normalMap`, as on a MeshPhongMaterial. Flat shading draws a triangle
 * soup of the knot (`toNonIndexed`), which keeps the uv the textures need.
 */
import { ShadingMaterial } from '@shadelab/material';
import * as THREE from 'three';
import { type DemoScene, disposeParts, scenePart } from './types';

/** Texture size (texels per side) and repeats over the knot's uv. */
export const TEXTURE = { size: 64, checks: 8, bumps: 4, repeat: [12, 2] as const };

/** The colour map: an 8 × 8 checker of a light and a warm grey (sRGB), multiplied into ka and kd. */
export function checkerTexture(): THREE.DataTexture {
  const { size, checks } = TEXTURE;
  const data = new Uint8Array(size * size * 4);
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const light = (Math.floor((x * checks) / size) + Math.floor((y * checks) / size)) % 2 === 0;
      const o = 4 * (y * size + x);
      data.set(light ? [235, 235, 225, 255] : [120, 90, 70, 255], o);
    }
  }
  return finish(new THREE.DataTexture(data, size, size), THREE.SRGBColorSpace);
}

/**
 * The normal map: `bumps` × `bumps` round bumps, height h = cos²-shaped; each texel holds the unit normal
 * (−∂h/∂x, −∂h/∂y, 1), normalised, in [0, 255] (tangent space, no colour space).
 */
export function bumpNormalTexture(): THREE.DataTexture {
  const { size, bumps } = TEXTURE;
  const data = new Uint8Array(size * size * 4);
  const cell = size / bumps;
  const strength = 2.5;
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      // Position inside the bump's cell, −1 … 1 at the texel's centre.
      const u = (((x + 0.5) % cell) / cell) * 2 - 1;
      const v = (((y + 0.5) % cell) / cell) * 2 - 1;
      const r = Math.hypot(u, v);
      // h = cos²(π r / 2) inside the unit disc: ∂h/∂r = −(π/2) sin(π r).
      const dhdr = r < 1 ? -(Math.PI / 2) * Math.sin(Math.PI * r) : 0;
      const dx = r > 0 ? (dhdr * u) / r : 0;
      const dy = r > 0 ? (dhdr * v) / r : 0;
      const n = new THREE.Vector3(-strength * dx * (2 / cell), -strength * dy * (2 / cell), 1).normalize();
      const o = 4 * (y * size + x);
      data.set(
        [
          Math.round((n.x * 0.5 + 0.5) * 255),
          Math.round((n.y * 0.5 + 0.5) * 255),
          Math.round((n.z * 0.5 + 0.5) * 255),
          255,
        ],
        o,
      );
    }
  }
  return finish(new THREE.DataTexture(data, size, size), THREE.NoColorSpace);
}

function finish(texture: THREE.DataTexture, colorSpace: THREE.ColorSpace): THREE.DataTexture {
  texture.colorSpace = colorSpace;
  texture.wrapS = THREE.RepeatWrapping;
  texture.wrapT = THREE.RepeatWrapping;
  texture.repeat.set(...TEXTURE.repeat);
  texture.magFilter = THREE.LinearFilter;
  texture.minFilter = THREE.LinearMipmapLinearFilter;
  texture.generateMipmaps = true;
  texture.needsUpdate = true;
  return texture;
}

export function createTexturedScene(): DemoScene {
  const map = checkerTexture();
  const normalMap = bumpNormalTexture();
  const material = new ShadingMaterial();
  // three's property names, as on MeshPhongMaterial.
  Object.assign(material, { map, normalMap });
  const geometry = new THREE.TorusKnotGeometry(1, 0.36, 200, 24);
  const mesh = new THREE.Mesh(geometry, material);
  mesh.name = 'textured torus knot';
  const parts = [scenePart(mesh, material, (shared) => shared.toNonIndexed())];
  return {
    root: mesh,
    parts,
    dispose: () => {
      disposeParts(parts);
      map.dispose();
      normalMap.dispose();
    },
  };
}
