// What a harness page reports of a call that should throw: the error's class and message, side by side for
// two implementations of the same API (the WebGL and the node materials).

/** `'<ErrorClass>: <message>'` of what `make` throws, or `'no error'`. */
export function thrown(make: () => unknown): string {
  try {
    make();
    return 'no error';
  } catch (e) {
    return `${(e as Error).constructor.name}: ${(e as Error).message}`;
  }
}
