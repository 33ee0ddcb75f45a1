// SPDX-License-Identifier: MIT
// The public structs as the module describes them (i2d_get_struct_infos and
// i2d_get_field_infos, read from its memory at load), and the fields this binding relies
// on. The binding lays no struct out itself: every offset and size it uses comes from
// the description, so a field added to a C header reaches it with no edit here. USES
// names each field it reads or writes and how; a module that lacks one or describes it
// otherwise is refused at load, naming every problem, instead of being misread.
import { DRAW_CALLBACK_FIELDS, DRAW_FLAG_FIELDS } from './draw_fields.js';
import { BASE_SETTINGS, FLAG, FLOAT, KIND_SETTINGS, POINT } from './joint_kinds.js';

/** i2d_field_kind's values (include/impulse2d/base.h) by name. */
export const KINDS = [undefined, 'bool', 'int8', 'int16', 'int32', 'int64', 'uint8', 'uint16', 'uint32', 'uint64',
  'float', 'double', 'pointer', 'function', 'struct'];

// The two structs that describe the others, as wasm32 lays them out: the only layouts
// written here, checked against the module's description of themselves.
const STRUCT_INFO = { name: 0, size: 4, align: 8, bytes: 12 };
const FIELD_INFO = { struct_name: 0, field_name: 4, type_name: 8, offset: 12, size: 16, count: 20, kind: 24, bytes: 28 };

const CROSSING_KIND = { [FLOAT]: 'float', [FLAG]: 'bool', [POINT]: 'i2d_vec2' };
const ID = 'i2d_shape_id';

/**
 * Every field the binding reads or writes, as it uses it: a kind ('float', 'int32',
 * 'bool', 'uint64'; an enum is 'int32'), a struct's C name ('i2d_vec2'), either with
 * '[]' for an array of any length, or a pointer to a type ('i2d_body_move_event*', 'void*').
 */
export const USES = {
  // Read and written as consecutive floats (see FIXED).
  i2d_vec2: { x: 'float', y: 'float' },
  i2d_rot: { c: 'float', s: 'float' },
  i2d_transform: { p: 'i2d_vec2', q: 'i2d_rot' },
  i2d_aabb: { min: 'i2d_vec2', max: 'i2d_vec2' },
  i2d_shape_id: { bits: 'uint64' },
  i2d_body_id: { bits: 'uint64' },
  i2d_joint_id: { bits: 'uint64' },
  i2d_world_def: {
    gravity: 'i2d_vec2', contact_slop: 'float', contact_hertz: 'float', contact_damping_ratio: 'float',
    contact_push_max_speed: 'float', restitution_threshold: 'float', maximum_linear_speed: 'float',
    enable_sleep: 'bool', sleep_speed_threshold: 'float', time_to_sleep: 'float', enable_contact_recycling: 'bool',
    joint_hertz: 'float', joint_damping_ratio: 'float', enable_continuous: 'bool',
    enable_impact_chains: 'bool', hit_event_threshold: 'float',
    length_units_per_meter: 'float',
  },
  i2d_body_def: {
    type: 'int32', position: 'i2d_vec2', rotation: 'i2d_rot', linear_velocity: 'i2d_vec2', angular_velocity: 'float',
    linear_damping: 'float', angular_damping: 'float', gravity_scale: 'float', fixed_rotation: 'bool',
    enable_sleep: 'bool', user_data: 'void*',
  },
  i2d_shape_def: {
    density: 'float', friction: 'float', restitution: 'float', is_sensor: 'bool', enable_contact_events: 'bool',
    enable_custom_filtering: 'bool', enable_pre_solve_events: 'bool', filter: 'i2d_filter',
  },
  i2d_filter: { category_bits: 'uint64', mask_bits: 'uint64', group_index: 'int32' },
  i2d_query_filter: { category_bits: 'uint64', mask_bits: 'uint64' },
  i2d_explosion_def: {
    mask_bits: 'uint64', position: 'i2d_vec2', radius: 'float', falloff: 'float', impulse_per_length: 'float',
  },
  // The character mover (mover.js).
  i2d_character_def: {
    max_slope_angle: 'float', step_height: 'float', snap_distance: 'float', skin: 'float', max_iterations: 'int32',
    push_mass: 'float', filter: 'i2d_query_filter',
  },
  i2d_character_result: {
    position: 'i2d_vec2', velocity: 'i2d_vec2', on_ground: 'bool', ground_normal: 'i2d_vec2', ground_shape: ID,
    ground_velocity: 'i2d_vec2', hit_count: 'int32',
  },
  i2d_plane: { normal: 'i2d_vec2', offset: 'float' },
  i2d_collision_plane: { plane: 'i2d_plane', push_limit: 'float', push: 'float', clip_velocity: 'bool' },
  i2d_plane_result: { translation: 'i2d_vec2', iteration_count: 'int32' },
  // Debug drawing (debug_draw.js): the callbacks are table slots the binding fills.
  i2d_debug_draw: {
    ...Object.fromEntries(DRAW_CALLBACK_FIELDS.map((f) => [f, 'function'])),
    drawing_bounds: 'i2d_aabb', use_drawing_bounds: 'bool',
    ...Object.fromEntries(DRAW_FLAG_FIELDS.map((f) => [f, 'bool'])),
    context: 'void*',
  },
  i2d_circle: { center: 'i2d_vec2', radius: 'float' },
  i2d_capsule: { center1: 'i2d_vec2', center2: 'i2d_vec2', radius: 'float' },
  i2d_segment: { point1: 'i2d_vec2', point2: 'i2d_vec2' },
  i2d_polygon: { vertices: 'i2d_vec2[]', radius: 'float', count: 'int32' },
  i2d_mass_data: { mass: 'float', center: 'i2d_vec2', rotational_inertia: 'float' },
  i2d_surface_material: { friction: 'float', restitution: 'float', rolling_resistance: 'float', tangent_speed: 'float' },
  i2d_manifold_point: { point: 'i2d_vec2', penetration: 'float', id: 'uint32' },
  i2d_manifold: { normal: 'i2d_vec2', point_count: 'int32', points: 'i2d_manifold_point[]' },
  i2d_contact_data: {
    shape_a: ID, shape_b: ID, manifold: 'i2d_manifold', normal_impulses: 'float[]', tangent_impulses: 'float[]',
  },
  i2d_shape_proxy: { points: 'i2d_vec2[]', count: 'int32', radius: 'float' },
  i2d_distance_result: { point_a: 'i2d_vec2', point_b: 'i2d_vec2', normal: 'i2d_vec2', distance: 'float' },
  i2d_world_counters: { body_count: 'int32', shape_count: 'int32', contact_count: 'int32', awake_body_count: 'int32' },
  i2d_body_events: { move_events: 'i2d_body_move_event*', move_count: 'int32' },
  i2d_body_move_event: { transform: 'i2d_transform', user_data: 'void*', fell_asleep: 'bool' },
  i2d_contact_events: {
    begin_events: 'i2d_contact_begin_event*', begin_count: 'int32',
    end_events: 'i2d_contact_end_event*', end_count: 'int32',
  },
  i2d_contact_begin_event: { shape_a: ID, shape_b: ID },
  i2d_contact_end_event: { shape_a: ID, shape_b: ID },
  i2d_ray_result: { shape: ID, point: 'i2d_vec2', normal: 'i2d_vec2', fraction: 'float', hit: 'bool' },
  i2d_joint_events: { events: 'i2d_joint_event*', count: 'int32' },
  i2d_joint_event: { joint: 'i2d_joint_id' },
  i2d_joint_base: {
    body_a: 'i2d_body_id', body_b: 'i2d_body_id',
    ...Object.fromEntries(Object.entries(BASE_SETTINGS).map(([f, crossing]) => [f, CROSSING_KIND[crossing]])),
  },
  // Each joint def: its base and the settings joint_kinds.js gives the kind.
  ...Object.fromEntries(Object.entries(KIND_SETTINGS).map(([kind, settings]) => [`i2d_${kind}_joint_def`, {
    base: 'i2d_joint_base',
    ...Object.fromEntries(Object.entries(settings).map(([f, crossing]) => [f, CROSSING_KIND[crossing]])),
  }])),
};

/**
 * Offsets and sizes the binding takes for granted: vectors and rotations cross as two
 * consecutive floats (Runtime.vec2, readVec2), a transform as four.
 */
export const FIXED = {
  'i2d_vec2': 8, 'i2d_vec2.x': 0, 'i2d_vec2.y': 4, 'i2d_rot': 8, 'i2d_rot.c': 0, 'i2d_rot.s': 4,
  'i2d_transform.p': 0, 'i2d_transform.q': 8,
};

/**
 * The module's description of its structs: Map of C name -> {name, size, align, fields:
 * Map of member -> {name, kind, typeName, offset, size, count}}, in the module's order.
 */
export function readDescription(module) {
  const out = module._malloc(4);
  const rows = (fn) => {
    const count = module[fn](out);
    return [module.HEAPU32[out >> 2], count];
  };
  const [structTable, structCount] = rows('_i2d_get_struct_infos');
  const [fieldTable, fieldCount] = rows('_i2d_get_field_infos');
  module._free(out);
  const u32 = module.HEAPU32, i32 = module.HEAP32;
  const text = (at) => module.UTF8ToString(u32[at >> 2]);
  const description = new Map();
  for (let i = 0; i < structCount; i++) {
    const at = structTable + i * STRUCT_INFO.bytes;
    const name = text(at + STRUCT_INFO.name);
    description.set(name, {
      name, size: i32[(at + STRUCT_INFO.size) >> 2], align: i32[(at + STRUCT_INFO.align) >> 2], fields: new Map(),
    });
  }
  for (let i = 0; i < fieldCount; i++) {
    const at = fieldTable + i * FIELD_INFO.bytes;
    const struct = description.get(text(at + FIELD_INFO.struct_name));
    const kind = i32[(at + FIELD_INFO.kind) >> 2];
    const field = {
      name: text(at + FIELD_INFO.field_name),
      kind: KINDS[kind] ?? `kind ${kind}`,
      typeName: text(at + FIELD_INFO.type_name),
      offset: i32[(at + FIELD_INFO.offset) >> 2],
      size: i32[(at + FIELD_INFO.size) >> 2],
      count: i32[(at + FIELD_INFO.count) >> 2],
    };
    if (struct !== undefined) struct.fields.set(field.name, field);
  }
  // The rows were read with the layouts above: the module must describe them so.
  const problems = [];
  for (const [name, layout] of [['i2d_struct_info', STRUCT_INFO], ['i2d_field_info', FIELD_INFO]]) {
    const struct = description.get(name);
    if (struct === undefined || struct.size !== layout.bytes) {
      problems.push(`${name}: size ${struct?.size}, expected ${layout.bytes}`);
      continue;
    }
    for (const [field, offset] of Object.entries(layout)) {
      if (field !== 'bytes' && struct.fields.get(field)?.offset !== offset) {
        problems.push(`${name}.${field}: offset ${struct.fields.get(field)?.offset}, expected ${offset}`);
      }
    }
  }
  if (problems.length > 0) {
    throw new Error(`impulse2d: the module describes its own description differently:\n  ${problems.join('\n  ')}`);
  }
  return description;
}

const SCALARS = new Set(['bool', 'int8', 'int16', 'int32', 'int64', 'uint8', 'uint16', 'uint32', 'uint64', 'float',
  'double', 'function']);

/** One line per field of `uses` the description lacks or describes otherwise. */
export function usageProblems(description, uses = USES, fixed = FIXED) {
  const problems = [];
  for (const [structName, used] of Object.entries(uses)) {
    const struct = description.get(structName);
    if (struct === undefined) {
      problems.push(`${structName}: not described by the module`);
      continue;
    }
    for (const [name, spec] of Object.entries(used)) {
      const field = struct.fields.get(name);
      if (field === undefined) {
        problems.push(`${structName}.${name}: the module has no such field; this binding uses it as ${spec}`);
        continue;
      }
      const [, base, pointer, array] = /^(\w+)(\*?)(\[\])?$/.exec(spec);
      const expected = pointer ? ['pointer', base] : SCALARS.has(base) ? [base, null] : ['struct', base];
      const actualType = expected[1] === null ? null : field.typeName;
      if (field.kind !== expected[0] || actualType !== expected[1] || (!array && field.count !== 1)) {
        const had = `${field.kind}${SCALARS.has(field.kind) ? '' : ` ${field.typeName}`}`;
        const count = field.count !== 1 ? `[${field.count}]` : '';
        problems.push(`${structName}.${name}: the module has ${had}${count}; this binding uses it as ${spec}`);
      }
    }
  }
  for (const [key, value] of Object.entries(fixed)) {
    const [structName, name] = key.split('.');
    const struct = description.get(structName);
    const actual = name === undefined ? struct?.size : struct?.fields.get(name)?.offset;
    if (actual !== value) {
      problems.push(`${key}: ${name === undefined ? 'size' : 'offset'} ${actual}; this binding takes ${value}`);
    }
  }
  return problems;
}

/** 'struct' -> size and 'struct.field' -> offset, for Runtime.size and Runtime.field. */
export function offsets(description) {
  const map = new Map();
  for (const struct of description.values()) {
    map.set(struct.name, struct.size);
    for (const field of struct.fields.values()) map.set(`${struct.name}.${field.name}`, field.offset);
  }
  return map;
}
