import { depthBufferParameters, depthModeOf } from '@shadelab/camera';
import { describe, expect, it } from 'vitest';

describe('depth modes', () => {
  it('maps each mode to the WebGLRenderer switches', () => {
    expect(depthBufferParameters('standard')).toEqual({
      logarithmicDepthBuffer: false,
      reversedDepthBuffer: false,
    });
    expect(depthBufferParameters('logarithmic')).toEqual({
      logarithmicDepthBuffer: true,
      reversedDepthBuffer: false,
    });
    expect(depthBufferParameters('reversed')).toEqual({
      logarithmicDepthBuffer: false,
      reversedDepthBuffer: true,
    });
    // Both of three's switches: three keeps reversed-Z when EXT_clip_control exists, logarithmic otherwise.
    expect(depthBufferParameters('reversed-or-logarithmic')).toEqual({
      logarithmicDepthBuffer: true,
      reversedDepthBuffer: true,
    });
    expect(() => depthBufferParameters('linear' as never)).toThrow(
      'mode must be one of standard, logarithmic, reversed, reversed-or-logarithmic, got linear',
    );
    expect(() => depthBufferParameters('linear' as never)).toThrow(RangeError);
  });

  it('reports what a renderer really uses (reversed wins, as in three)', () => {
    const of = (reversedDepthBuffer: boolean, logarithmicDepthBuffer: boolean) =>
      depthModeOf({ capabilities: { reversedDepthBuffer, logarithmicDepthBuffer } as never });
    expect(of(false, false)).toBe('standard');
    expect(of(false, true)).toBe('logarithmic');
    expect(of(true, false)).toBe('reversed');
  });
});
