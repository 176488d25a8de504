/**
 * The Khronos glTF Validator's check of a file that passed `gltfCheck.ts`: the JSON schema, every reference,
 * buffer and view length, accessor and image. The `gltf-validator` package is imported on the first call; this
 * module is imported only by the model loader, so neither is in the page's first load. Unit-tested in
 * gltfCheck.test.ts.
 */
import { type CheckedModel, ModelError } from './gltfCheck';

/**
 * Validator errors about values, not structure, that three draws as they are: bounds that do not match the data
 * (exporters round them), normals, tangents, weights and rotations a little off unit length or sum, colours
 * outside 0..1, a joint listed twice, a material asking for tangents three derives in the shader. Downloaded
 * models often have them, and three draws those models: they are not refused (reported as warnings, not read).
 * Every other error refuses the file.
 */
export const DRAWN_ANYWAY: readonly string[] = [
  'ACCESSOR_MIN_MISMATCH',
  'ACCESSOR_MAX_MISMATCH',
  'ACCESSOR_ELEMENT_OUT_OF_MIN_BOUND',
  'ACCESSOR_ELEMENT_OUT_OF_MAX_BOUND',
  'ACCESSOR_VECTOR3_NON_UNIT',
  'ACCESSOR_INVALID_SIGN',
  'ACCESSOR_WEIGHTS_NON_NORMALIZED',
  'ACCESSOR_ANIMATION_SAMPLER_OUTPUT_NON_NORMALIZED_QUATERNION',
  'ACCESSOR_NON_CLAMPED',
  'ACCESSOR_JOINTS_INDEX_DUPLICATE',
  'ROTATION_NON_UNIT',
  'MESH_PRIMITIVE_NO_TANGENT_SPACE',
];

/** One finding of the validator's report (`issues.messages`). */
interface ValidatorMessage {
  code: string;
  message: string;
  /** 0 error, 1 warning, 2 information, 3 hint. */
  severity: number;
  /** A JSON pointer to the object at fault, or the byte offset in a GLB. */
  pointer?: string;
  offset?: number;
}

/** Findings shown in a refusal's message (the first ones, in the validator's order). */
const SHOWN_ERRORS = 3;

/**
 * Validates a checked file with the Khronos glTF Validator (loaded on first call); throws a {@link ModelError}
 * naming the file, how many errors it has and the first ones, each with where it is in the file. Errors in
 * {@link DRAWN_ANYWAY} do not refuse it; warnings and notes never do.
 */
export async function validateModel(name: string, checked: CheckedModel): Promise<void> {
  const validator = await import('gltf-validator');
  const options = {
    uri: name,
    writeTimestamp: false,
    severityOverrides: Object.fromEntries(DRAWN_ANYWAY.map((code) => [code, 1])),
  };
  const report =
    typeof checked.data === 'string'
      ? await validator.validateString(checked.data, options)
      : await validator.validateBytes(new Uint8Array(checked.data), { ...options, format: 'glb' });
  const messages = report.issues.messages as ValidatorMessage[];
  const errors = messages.filter((m) => m.severity === 0);
  const count = Math.max(report.issues.numErrors, errors.length);
  if (count === 0) return;
  const where = (m: ValidatorMessage) =>
    m.pointer !== undefined ? m.pointer : m.offset !== undefined ? `byte ${m.offset}` : 'the file';
  const shown = errors.slice(0, SHOWN_ERRORS).map((m) => `${where(m)}: ${m.message}`);
  throw new ModelError(
    `"${name}" is not valid glTF: the Khronos glTF Validator found ${count === 1 ? 'an error' : `${count} errors`}: ${shown.join('; ')}${count > shown.length ? '; …' : ''}`,
  );
}
