// SPDX-License-Identifier: MIT
// The character mover (include/impulse2d/toolkit.h, docs/character_mover.md): the
// one-call World.moveCharacter, the queries World.castMover and World.collideMover, and
// the pure plane calls solvePlanes and clipVector, over the module's memory.
import { readQueryFilter, writeQueryFilter } from './filters.js';
import { vx, vy } from './vectors.js';

/** i2d_character_def's settings by option name. */
const CHARACTER_SETTINGS = {
  maxSlopeAngle: 'max_slope_angle', stepHeight: 'step_height', snapDistance: 'snap_distance', skin: 'skin',
  maxIterations: 'max_iterations', pushMass: 'push_mass',
};
const MOVE_ARGUMENTS = ['capsule', 'position', 'velocity', 'timeStep'];
const MOVE_OPTIONS = [...MOVE_ARGUMENTS, ...Object.keys(CHARACTER_SETTINGS), 'filter'];
/** FLT_MAX, a rigid plane's push_limit (i2d_world_collide_mover gives it). */
const RIGID_PUSH_LIMIT = 3.4028234663852886e38;

/** The default character def as options: {maxSlopeAngle, ..., filter}. */
export function defaultCharacterDef(rt) {
  const def = rt.defBlock('character');
  try {
    const field = (name) => def + rt.field(`i2d_character_def.${name}`);
    const out = {};
    for (const [option, name] of Object.entries(CHARACTER_SETTINGS)) {
      out[option] = name === 'max_iterations' ? rt.i32[field(name) >> 2] : rt.f32[field(name) >> 2];
    }
    out.filter = readQueryFilter(rt, field('filter'));
    return out;
  } finally {
    rt.m._free(def);
  }
}

/** World.moveCharacter: one move, its result with the world's Shape for the ground. */
export function moveCharacter(world, options) {
  const rt = world.rt;
  checkMoveOptions(options);
  const def = rt.defBlock('character');
  try {
    writeCharacterDef(rt, def, options);
    const { position, velocity } = options;
    const out = rt.result();
    rt.check(rt.m._i2d_world_move_character(world.id, def, writeCapsule(rt, rt.arg(0), options.capsule),
                                            rt.vec2(1, vx(position), vy(position)),
                                            rt.vec2(2, vx(velocity), vy(velocity)), Number(options.timeStep), out));
    return readCharacterResult(world, out);
  } finally {
    rt.m._free(def);
  }
}

/** World.castMover: the fraction of translation the capsule can move, in [0, 1]. */
export function castMover(world, capsule, translation, filter) {
  const rt = world.rt;
  const filterAt = writeQueryFilter(rt, rt.arg(2), filter, 'castMover\'s filter');
  const fraction = rt.m._i2d_world_cast_mover(world.id, writeCapsule(rt, rt.arg(0), capsule),
                                              rt.vec2(1, vx(translation), vy(translation)), filterAt);
  rt.checkLast();
  return fraction;
}

/** World.collideMover: a plane per shape within the contact slop of the capsule. */
export function collideMover(world, capsule, filter) {
  const rt = world.rt;
  const stride = rt.size('i2d_collision_plane');
  const fill = (out, capacity) => {
    // The argument slots are written for each call: filled() may call again after a malloc.
    const filterAt = writeQueryFilter(rt, rt.arg(1), filter, 'collideMover\'s filter');
    return rt.m._i2d_world_collide_mover(world.id, writeCapsule(rt, rt.arg(0), capsule), filterAt, out, capacity);
  };
  const read = (out, count) => Array.from({ length: count }, (_, i) => readPlane(rt, out + i * stride));
  return rt.filled(stride, fill, read);
}

/** Impulse2d.solvePlanes: {translation, iterationCount, pushes (one per plane)}. */
export function solvePlanes(rt, targetDelta, planes) {
  return withPlanes(rt, planes, 'solvePlanes', (at, count) => {
    const out = rt.result();
    rt.m._i2d_solve_planes(out, rt.vec2(0, vx(targetDelta), vy(targetDelta)), at, count);
    rt.checkLast();
    const stride = rt.size('i2d_collision_plane');
    return {
      translation: rt.readVec2(out + rt.field('i2d_plane_result.translation')),
      iterationCount: rt.i32[(out + rt.field('i2d_plane_result.iteration_count')) >> 2],
      pushes: Array.from({ length: count },
                         (_, i) => rt.f32[(at + i * stride + rt.field('i2d_collision_plane.push')) >> 2]),
    };
  });
}

/** Impulse2d.clipVector: the vector less its part running into planes that clip. */
export function clipVector(rt, vector, planes) {
  return withPlanes(rt, planes, 'clipVector', (at, count) => {
    rt.m._i2d_clip_vector(rt.result(), rt.vec2(0, vx(vector), vy(vector)), at, count);
    rt.checkLast();
    return rt.readVec2(rt.result());
  });
}

function checkMoveOptions(options) {
  if (options === null || typeof options !== 'object') {
    throw new TypeError(`World.moveCharacter takes {${MOVE_ARGUMENTS.join(', ')}, ...settings}`);
  }
  for (const name of Object.keys(options)) {
    if (!MOVE_OPTIONS.includes(name)) {
      throw new TypeError(`a character move has no setting '${name}'; known: ${MOVE_OPTIONS.join(', ')}`);
    }
  }
}

// A setting left out keeps the default def's value; a missing capsule, position,
// velocity or time step reads as NaN, which the library refuses with its own message.
function writeCharacterDef(rt, def, options) {
  const field = (name) => def + rt.field(`i2d_character_def.${name}`);
  for (const [option, name] of Object.entries(CHARACTER_SETTINGS)) {
    const value = options[option];
    if (value === undefined) continue;
    if (name === 'max_iterations') rt.i32[field(name) >> 2] = value;
    else rt.f32[field(name) >> 2] = value;
  }
  if (options.filter !== undefined) writeQueryFilter(rt, field('filter'), options.filter, 'the character\'s filter');
}

/** An i2d_capsule {center1, center2, radius} at `at`, as Shape.geometry gives one. */
function writeCapsule(rt, at, capsule) {
  const field = (name) => at + rt.field(`i2d_capsule.${name}`);
  rt.writeVec2(field('center1'), vx(capsule?.center1), vy(capsule?.center1));
  rt.writeVec2(field('center2'), vx(capsule?.center2), vy(capsule?.center2));
  rt.f32[field('radius') >> 2] = Number(capsule?.radius);
  return at;
}

function readCharacterResult(world, at) {
  const rt = world.rt;
  const field = (name) => at + rt.field(`i2d_character_result.${name}`);
  const onGround = rt.u8[field('on_ground')] !== 0;
  const ground = rt.u64[field('ground_shape') >> 3];
  return {
    position: rt.readVec2(field('position')),
    velocity: rt.readVec2(field('velocity')),
    onGround,
    groundNormal: rt.readVec2(field('ground_normal')),
    // A shape the package did not make comes as its id; none, as null.
    groundShape: ground === 0n ? null : world.shapeById.get(ground) ?? ground,
    groundVelocity: rt.readVec2(field('ground_velocity')),
    hitCount: rt.i32[field('hit_count') >> 2],
  };
}

/** A collision plane as {normal, offset, pushLimit, push, clipVelocity}. */
function readPlane(rt, at) {
  const field = (name) => at + rt.field(`i2d_collision_plane.${name}`);
  const plane = field('plane');
  return {
    normal: rt.readVec2(plane + rt.field('i2d_plane.normal')),
    offset: rt.f32[(plane + rt.field('i2d_plane.offset')) >> 2],
    pushLimit: rt.f32[field('push_limit') >> 2],
    push: rt.f32[field('push') >> 2],
    clipVelocity: rt.u8[field('clip_velocity')] !== 0,
  };
}

// pushLimit: left out or Infinity is rigid (the C API's FLT_MAX); clipVelocity: default
// true. A missing normal or offset reads as NaN, refused by the library.
function writePlane(rt, at, plane) {
  const field = (name) => at + rt.field(`i2d_collision_plane.${name}`);
  const base = field('plane');
  rt.writeVec2(base + rt.field('i2d_plane.normal'), vx(plane?.normal), vy(plane?.normal));
  rt.f32[(base + rt.field('i2d_plane.offset')) >> 2] = Number(plane?.offset);
  const limit = plane?.pushLimit ?? RIGID_PUSH_LIMIT;
  rt.f32[field('push_limit') >> 2] = limit === Infinity ? RIGID_PUSH_LIMIT : limit;
  rt.f32[field('push') >> 2] = 0;
  rt.u8[field('clip_velocity')] = (plane?.clipVelocity ?? true) ? 1 : 0;
}

/** Copies planes into a block of the module's memory for use(at, count), then frees it. */
function withPlanes(rt, planes, method, use) {
  if (!Array.isArray(planes)) throw new TypeError(`${method} takes an array of planes, not ${String(planes)}`);
  const stride = rt.size('i2d_collision_plane');
  const at = rt.m._malloc(Math.max(1, planes.length) * stride);
  try {
    planes.forEach((plane, i) => writePlane(rt, at + i * stride, plane));
    return use(at, planes.length);
  } finally {
    rt.m._free(at);
  }
}
