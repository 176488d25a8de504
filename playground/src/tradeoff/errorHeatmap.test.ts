import { linearToSrgb8 } from '@shadelab/material';
import {
  compareToReference,
  type ImageError,
  type ReferenceImage,
  renderReference,
} from '@shadelab/reference';
import { OrthographicCamera } from 'three';
import { describe, expect, it } from 'vitest';
import {
  errorHeatmap,
  HEAT_BACKGROUND,
  HEAT_EXACT,
  HEAT_RAMP_STOPS,
  heatColor,
  silhouetteColor,
} from './errorHeatmap';

/** A 4×3 stand-in: only the fields errorHeatmap reads. */
function fixture(
  hit: number[],
  colorError: number[],
  silhouetteError: number[],
): { error: ImageError; reference: ReferenceImage } {
  const reference = { width: 4, height: 3, hit: Uint8Array.from(hit) } as unknown as ReferenceImage;
  const error = {
    colorError: Uint8Array.from(colorError),
    silhouetteError: Float32Array.from(silhouetteError),
  } as unknown as ImageError;
  return { error, reference };
}

/** RGB of pixel (i, j), j counted from the bottom like the reference, out of a top-down heat map. */
function at(map: Uint8ClampedArray, width: number, height: number, i: number, j: number): number[] {
  const o = 4 * ((height - 1 - j) * width + i);
  return [map[o], map[o + 1], map[o + 2], map[o + 3]];
}

describe('errorHeatmap', () => {
  it('exact interior → dark grey (the legend colour), background → black, silhouette → cyan; rows flipped', () => {
    // Row 0 (bottom): background, exact, error 8, silhouette 1 px. Row 1: exact ×4. Row 2: error 16 ×2, bg ×2.
    const { error, reference } = fixture(
      [0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0],
      [0, 0, 8, 0, 0, 0, 0, 0, 16, 40, 0, 0],
      [0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0],
    );
    const map = errorHeatmap(error, reference);
    expect(map.length).toBe(4 * 12);
    expect(at(map, 4, 3, 0, 0)).toEqual([...HEAT_BACKGROUND, 255]);
    expect(HEAT_BACKGROUND).toEqual([0, 0, 0]);
    expect(at(map, 4, 3, 1, 0)).toEqual([...HEAT_EXACT, 255]);
    expect(HEAT_EXACT).toEqual([40, 40, 40]); // grey, as the legend says, not black
    expect(at(map, 4, 3, 2, 0)).toEqual([255, 255, 0, 255]); // 8 codes: yellow
    const cyan = at(map, 4, 3, 3, 0);
    expect(cyan[0]).toBe(0);
    expect(cyan[1]).toBe(cyan[2]);
    expect(cyan[1]).toBeGreaterThan(0);
    for (let i = 0; i < 4; i++) expect(at(map, 4, 3, i, 1)).toEqual([...HEAT_EXACT, 255]);
    expect(at(map, 4, 3, 0, 2)).toEqual([255, 0, 0, 255]); // 16 codes: red
    expect(at(map, 4, 3, 1, 2)).toEqual([255, 0, 0, 255]); // 40: red too
    // The top row of the image is the reference's last row.
    expect(Array.from(map.slice(0, 4))).toEqual([255, 0, 0, 255]);
  });

  it('a silhouette mismatch wins over the colour of a covered pixel, and is brighter the farther it is', () => {
    const { error, reference } = fixture(
      [1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0],
      [9, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0],
      [0.25, 1, 3, 0.5, 0, 0, 0, 0, 0, 0, 0, 0],
    );
    const map = errorHeatmap(error, reference);
    const g = [0, 1, 2].map((i) => at(map, 4, 3, i, 0)[1]);
    expect(g[0]).toBeLessThan(g[1]);
    expect(g[1]).toBeLessThan(g[2]);
    expect(g[2]).toBe(255); // saturates from 2.6 px
    expect(at(map, 4, 3, 3, 0)).toEqual([...silhouetteColor(0.5), 255]); // outside pixels too
    for (let i = 0; i < 4; i++) expect(at(map, 4, 3, i, 0)[0]).toBe(0);
  });

  it('the ramp: 0 grey, then olive → yellow at 8 → red at 16+, red rising, green peaking at 8, never blue', () => {
    expect(heatColor(0)).toEqual(HEAT_EXACT);
    expect(heatColor(8)).toEqual([255, 255, 0]);
    expect(heatColor(16)).toEqual([255, 0, 0]);
    expect(heatColor(255)).toEqual([255, 0, 0]);
    expect(HEAT_RAMP_STOPS).toEqual([1, 8, 16]);
    const one = heatColor(1);
    expect(one).not.toEqual(HEAT_EXACT); // one code of error is visible
    expect(one[0]).toBeGreaterThan(HEAT_EXACT[0]);
    for (let e = 1; e < 64; e++) {
      const [r, g, b] = heatColor(e);
      const [r2, g2] = heatColor(e + 1);
      expect(b).toBe(0);
      expect(r2).toBeGreaterThanOrEqual(r);
      if (e < 8) expect(g2).toBeGreaterThanOrEqual(g);
      else expect(g2).toBeLessThanOrEqual(g);
    }
  });

  it('on a real comparison: a perfect image is grey and black only; shifted by a pixel, exactly its mismatches are cyan', () => {
    const N = 40;
    const camera = new OrthographicCamera(-1.25, 1.25, 1.25, -1.25, 0.1, 10);
    camera.position.set(0, 0, 3);
    camera.updateMatrixWorld();
    const reference = renderReference({
      width: N,
      height: N,
      projectionMatrix: camera.projectionMatrix.elements,
      viewMatrix: camera.matrixWorldInverse.elements,
      material: { ka: [0.3, 0.2, 0.1], kd: [0.6, 0.35, 0.2], ks: [0.5, 0.5, 0.5], shininess: 32 },
      lights: [{ position: [-5, 10, 20], ambient: [1, 1, 1], diffuse: [1, 1, 1], specular: [1, 1, 1] }],
    });
    const image = (shift: number) => {
      const out = new Uint8Array(4 * N * N);
      for (let k = 0; k < N * N; k++) {
        const s = Math.floor(k / N) * N + Math.min(Math.max((k % N) - shift, 0), N - 1);
        const c = reference.hit[s]
          ? linearToSrgb8([reference.linear[3 * s], reference.linear[3 * s + 1], reference.linear[3 * s + 2]])
          : [0, 0, 255];
        out.set([c[0], c[1], c[2], 255], 4 * k);
      }
      return out;
    };
    const isCyan = (m: Uint8ClampedArray, o: number) => m[o] === 0 && m[o + 1] > 0 && m[o + 1] === m[o + 2];
    const perfect = errorHeatmap(compareToReference(image(0), reference), reference);
    for (let o = 0; o < perfect.length; o += 4) {
      const rgb = [perfect[o], perfect[o + 1], perfect[o + 2]];
      expect([HEAT_EXACT, HEAT_BACKGROUND].some((c) => c.every((v, i) => v === rgb[i]))).toBe(true);
    }
    const shifted = compareToReference(image(1), reference);
    const map = errorHeatmap(shifted, reference);
    let cyan = 0;
    for (let o = 0; o < map.length; o += 4) if (isCyan(map, o)) cyan++;
    expect(shifted.mismatchedPixels).toBeGreaterThan(10);
    expect(cyan).toBe(shifted.mismatchedPixels);
  });
});
