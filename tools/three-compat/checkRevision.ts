// Fails the run unless the tests really get the pinned three: the alias must not silently fall back to the
// repository's own three.
import { REVISION } from 'three';

declare const __THREE_COMPAT_VERSION__: string;

const expected = __THREE_COMPAT_VERSION__.split('.')[1];
if (REVISION !== expected) {
  throw new Error(
    `three-compat: tests resolved three r${REVISION}, expected r${expected} (tools/three-compat)`,
  );
}
