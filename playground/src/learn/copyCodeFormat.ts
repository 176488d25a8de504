/**
 * Copy as code: how values are written in the generated source (numbers in JavaScript's shortest round-trip
 * form, so the program reads back the exact doubles the playground used), and the import list the emitters
 * collect as they go.
 */
import type { Literal, Options } from './copyCodeModel';

/**
 * A number as source text, to 15 significant digits (DBL_DIG: every such decimal survives a trip through a
 * double), in its shortest form: the noise arithmetic leaves below them goes (`-0.20000000000000018` is written
 * `-0.2`), and the value read back is within 5e-15 of the state's, relatively (far below a float32's precision:
 * its pictures are the playground's pixels). `-0` is written `0`.
 */
export function num(value: number): string {
  if (value === 0) return '0';
  if (!Number.isFinite(value)) return String(value);
  return String(Number(value.toPrecision(15)));
}

/** A list of numbers: `[1, 2, 3]`. */
export function numbers(values: readonly number[]): string {
  return `[${values.map(num).join(', ')}]`;
}

/** Whether `value` is a colour triple `[r, g, b]` (the material's and light's colour options). */
const isTriple = (value: Literal): value is readonly number[] =>
  Array.isArray(value) && value.length === 3 && value.every((v) => typeof v === 'number');

/**
 * A value as a TypeScript literal. A grey colour triple (r = g = b) is written as one number where `greys` is
 * set: the packages' constructors read a number as a grey level (R3F props do not: there a number is a hex
 * colour, so the props keep the triple).
 */
export function literal(value: Literal, greys = true): string {
  if (typeof value === 'number') return num(value);
  if (typeof value === 'string') return `'${value.replace(/\\/g, '\\\\').replace(/'/g, "\\'")}'`;
  if (typeof value === 'boolean') return String(value);
  if (Array.isArray(value)) {
    if (greys && isTriple(value) && value[0] === value[1] && value[1] === value[2]) return num(value[0]!);
    return `[${value.map((v) => literal(v, greys)).join(', ')}]`;
  }
  return objectLiteral(value as Options, greys);
}

/** An options object: `{ a: 1, b: 'x' }`, or `{}` when empty. */
export function objectLiteral(options: Options, greys = true): string {
  const entries = Object.entries(options);
  if (entries.length === 0) return '{}';
  return `{ ${entries.map(([k, v]) => `${/^[A-Za-z_$][\w$]*$/.test(k) ? k : `'${k}'`}: ${literal(v, greys)}`).join(', ')} }`;
}

/** Constructor arguments: nothing for no options, else the options object. */
export function args(options: Options): string {
  return Object.keys(options).length === 0 ? '' : objectLiteral(options);
}

/** The imports a program collects: module → names, printed in a stable order. */
export class Imports {
  private readonly modules = new Map<string, Set<string>>();

  /** Adds `names` from `module`; a name `* as X` is a namespace import. Returns the first name (for chaining). */
  add(module: string, ...names: string[]): string {
    let set = this.modules.get(module);
    if (!set) {
      set = new Set();
      this.modules.set(module, set);
    }
    for (const name of names) set.add(name);
    return names[0] ?? '';
  }

  /** The import lines, sorted by module name; type-only names are written `type X`. */
  toString(): string {
    return [...this.modules.entries()]
      .sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0))
      .map(([module, names]) => {
        // A name imported as a value is also its type.
        const list = [...names].filter((n) => !(n.startsWith('type ') && names.has(n.slice(5))));
        const namespace = list.find((n) => n.startsWith('* as '));
        if (namespace) return `import ${namespace} from '${module}';`;
        list.sort((a, b) => a.replace(/^type /, '').localeCompare(b.replace(/^type /, '')));
        return `import { ${list.join(', ')} } from '${module}';`;
      })
      .join('\n');
  }
}

/** A JSX attribute: `name={value}` (`name="value"` for a string), or `name` for `true`. */
export function attribute(name: string, value: Literal, greys = false): string {
  if (value === true) return name;
  if (typeof value === 'string') return `${name}="${value}"`;
  return `${name}={${literal(value, greys)}}`;
}

/** JSX attributes for every option, in order. */
export function attributes(options: Options, greys = false): string {
  return Object.entries(options)
    .map(([k, v]) => ` ${attribute(k, v, greys)}`)
    .join('');
}

/** A scene's builder: its function's source and what the program does with the result. */
export interface SceneCode {
  /** The function declaration, pasted above the program. */
  declaration: string;
  /** The expression that builds the scene's object, given `material` (an expression making a ShadingMaterial). */
  build(material: string): string;
  /** The scene's fog and background colour (three.js `Fog`), when it has them. */
  fog?: { color: string; near: number; far: number };
  /** Whether it needs `renderer.localClippingEnabled`. */
  clipping?: boolean;
  /** An expression for what stays in world space, outside the trackball (a model's light rig). */
  world?: string;
}

/** The outline of each of `meshes` (an expression listing them), when `outline` is set. */
export function outlineEach(imports: Imports, meshes: string, outline: Options | null): string {
  if (!outline) return '';
  imports.add('@shadelab/material/outline', 'createOutline');
  const options = Object.keys(outline).length ? `, ${objectLiteral(outline)}` : '';
  return `  for (const outlined of ${meshes}) createOutline(outlined${options});\n`;
}
