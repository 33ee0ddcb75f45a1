// SPDX-License-Identifier: MIT
// A world: stepping, bodies, joints, queries, events and snapshots over an i2d_world_id.
import { Body, BODY_TYPES } from './body.js';
import { BodyMoves } from './body_moves.js';
import { drawWorld } from './debug_draw.js';
import { ContactHooks } from './hooks.js';
import { createJoint } from './joint.js';
import { readManifold } from './manifold.js';
import { castMover, collideMover, moveCharacter } from './mover.js';
import { Shape } from './shape.js';
import { Recorder } from './recording.js';
import { rememberStructure, saveBytes, structureOf, withBytesInModule } from './snapshot.js';
import { vx, vy } from './vectors.js';

/** i2d_simd_path's values by name, in order: createWorld's simdPath takes a name or the
 *  number. A path this build cannot run ('sse2' in WebAssembly) is refused. */
export const SIMD_PATH_NAMES = Object.freeze(['automatic', 'scalar', 'sse2', 'avx2', 'avx512', 'neon', 'wasm128']);

export class World {
  /** @internal Made by Impulse2d.createWorld and World.fromSnapshot. */
  constructor(rt, id) {
    this.rt = rt;
    this.id = id;
    /** Live bodies by index (the user data their move events carry); slot 0 unused. */
    this.bodyByIndex = [undefined];
    this.freeIndices = [];
    this.shapeById = new Map();
    /** Live joints by id, in creation order: what joint events are mapped back through. */
    this.jointById = new Map();
    /** @internal The custom filter and pre-solve functions set on the world. */
    this.hooks = new ContactHooks(this);
    /** @internal The build's worker threads this world holds (workerCount - 1). */
    this.threads = 0;
    /** @internal The recording in progress (startRecording), or null. */
    this.recorder = null;
    /** @internal What owns the world and destroys it ('replay'), or null: the user's. */
    this.owner = null;
  }

  /** @internal A new world with the given options (Impulse2d.createWorld). */
  static create(rt, options = {}) {
    const threads = threadsFor(rt, options.workerCount);
    const def = rt.defBlock('world');
    try {
      if (options.lengthUnitsPerMeter !== undefined) {
        // The defaults of a world in those units (i2d_default_world_def_in_units).
        rt.m._i2d_default_world_def_in_units(def, options.lengthUnitsPerMeter);
        rt.checkLast();
      }
      writeWorldDef(rt, def, options);
      rt.i32[(def + rt.field('i2d_world_def.worker_count')) >> 2] = threads + 1;
      const world = new World(rt, rt.checkId(rt.m._i2d_world_create(def)));
      world.threads = threads;
      rt.threadsLent += threads;
      return world;
    } finally {
      rt.m._free(def);
    }
  }

  /** How many workers step the world (createWorld's workerCount; 1 but in the threads build). */
  get workerCount() { return this.threads + 1; }

  /**
   * A new world from a snapshot's bytes (i2d_world_create_from_snapshot): it steps on
   * bit for bit as the saved world would. Bytes that takeSnapshot returned bring new
   * Body, Shape and Joint objects for what the saved world held (same indices, userData
   * copied); other bytes (a file, another process) leave the world without objects.
   * WebAssembly has no host wiring to choose (one thread, the module's widest kernels),
   * so there are no options. A refused buffer throws I2D_ERR_INVALID_SNAPSHOT with the library's message.
   */
  static fromSnapshot(impulse2d, bytes) {
    const rt = impulse2d.rt;
    const id = withBytesInModule(rt, bytes, (at, length) => rt.m._i2d_world_create_from_snapshot(at, length, 0));
    const world = new World(rt, rt.checkId(id));
    const structure = structureOf(bytes, rt);
    if (structure !== undefined) world.adoptStructure(structure);
    return world;
  }

  /**
   * Starts recording the world (i2d_world_start_recording): a snapshot, then every call
   * that changes it and every step with the state hash it produced, for Impulse2d.openReplay.
   * With `write`, each record is handed to write(Uint8Array) as it is made (append it to a
   * file or a buffer; the world is locked meanwhile, and an error write throws is kept and
   * thrown by stopRecording); without, stopRecording returns the whole recording.
   * Recording again starts a new recording.
   */
  startRecording(write) {
    if (this.recorder) this.stopRecording();
    this.recorder = new Recorder(this, write);
  }

  /** Stops recording: the recording's bytes if startRecording kept them, else undefined. */
  stopRecording() {
    const recorder = this.recorder;
    if (!recorder) return undefined;
    this.recorder = null;
    return recorder.stop();
  }

  /** The world saved to portable bytes (i2d_world_save_snapshot), for restoreSnapshot,
   *  World.fromSnapshot, a file or another machine. */
  takeSnapshot() {
    const bytes = saveBytes(this.rt, this.id, '_i2d_world_get_snapshot_size', '_i2d_world_save_snapshot');
    rememberStructure(bytes, this);
    return bytes;
  }

  /**
   * Replaces the world's state with a snapshot's (i2d_world_restore_snapshot). The world
   * keeps its id; what existed at the save exists again (the same objects, for bytes this
   * world's takeSnapshot returned), what was made since is gone. A refused buffer throws
   * I2D_ERR_INVALID_SNAPSHOT and leaves the world, and its objects, as they were.
   */
  restoreSnapshot(bytes) {
    const rt = this.rt;
    rt.check(withBytesInModule(rt, bytes, (at, length) => rt.m._i2d_world_restore_snapshot(this.id, at, length)));
    const structure = structureOf(bytes, rt);
    if (structure !== undefined) this.adoptStructure(structure);
    else this.forgetStale();
  }

  /** A rollback state (i2d_world_save_state): what a step changes, for restoreState in
   *  this world while its bodies, shapes and joints stay as they are. */
  saveState() {
    return saveBytes(this.rt, this.id, '_i2d_world_get_state_size', '_i2d_world_save_state');
  }

  /**
   * Brings the world back to a state saveState took from it; stepping on gives the same
   * bits as stepping from that moment did. Another world's state, one saved before a body,
   * shape, joint (or joint setting) or gravity changed, or bytes that are truncated or
   * corrupted, throw I2D_ERR_INVALID_SNAPSHOT and leave the world as it was.
   */
  restoreState(bytes) {
    const rt = this.rt;
    rt.check(withBytesInModule(rt, bytes, (at, length) => rt.m._i2d_world_restore_state(this.id, at, length)));
  }

  isValid() { return this.rt.m._i2d_world_is_valid(this.id) !== 0; }

  /** Advances by timeStep seconds in substeps equal substeps; then throws the first error
   *  a contact hook threw during the step, if one did. */
  step(timeStep = 1 / 60, substeps = 4) {
    const status = this.rt.m._i2d_world_step(this.id, timeStep, substeps);
    const raised = this.hooks.takeRaised();
    this.rt.check(status);
    if (raised.length > 0) throw raised[0];
  }

  /**
   * fn(shapeA, shapeB) decides whether two shapes may ever touch (false: they pass through
   * each other); null clears it. Asked when the pair is found, for pairs where either
   * shape has enableCustomFiltering. Runs inside step() as setPreSolve's hook does.
   */
  setCustomFilter(fn) { this.hooks.set('customFilter', fn, 'setCustomFilter'); }

  /**
   * fn(shapeA, shapeB, manifold) decides whether a touching contact takes part in this
   * step (false: no impulse, no begin event this step); null clears it. Asked every step
   * the pair touches, for pairs where either shape has enablePreSolveEvents; manifold is
   * {normal (from A to B), points: [{point, penetration, id}]}. The hooks run inside
   * step(), on its thread; the world is locked meanwhile (any call on it throws
   * I2D_ERR_WORLD_LOCKED). An error a hook throws gives the pair true and is thrown by
   * step() once the step is done.
   */
  setPreSolve(fn) { this.hooks.set('preSolve', fn, 'setPreSolve'); }

  /**
   * A blast at position (i2d_world_explode): every dynamic body with a shape within
   * radius (default 1) + falloff (default 0) of it, whose category meets maskBits (default
   * every bit; a number or a BigInt), is pushed away by impulsePerLength (default 1) N s
   * per length of its outline facing the blast, fading linearly over the falloff, and
   * woken. A negative impulse pulls. A setting the blast does not have is a TypeError.
   */
  explode(options = {}) {
    const rt = this.rt;
    const def = rt.defBlock('explosion');
    try {
      writeExplosionDef(rt, def, options);
      rt.check(rt.m._i2d_world_explode(this.id, def));
    } finally {
      rt.m._free(def);
    }
  }

  /**
   * Moves a character (i2d_world_move_character): options are {capsule: {center1, center2,
   * radius} in the character's frame, position, velocity, timeStep} and any setting of
   * Impulse2d.defaultCharacterDef() to change (maxSlopeAngle, stepHeight, snapDistance,
   * skin, maxIterations, pushMass, filter). Returns {position, velocity (clipped by what
   * it touches; add groundVelocity to ride a platform), onGround, groundNormal,
   * groundShape (a Shape, or null), groundVelocity, hitCount}. Changes nothing in the
   * world but the pushes it gives dynamic bodies (none with pushMass 0). A setting it
   * does not have is a TypeError; a bad value an Impulse2dError, the world untouched.
   */
  moveCharacter(options) { return moveCharacter(this, options); }

  /** The fraction in [0, 1] of translation the capsule (world coordinates) can move before
   *  it comes within the contact slop of a shape the filter ({categoryBits, maskBits};
   *  default every shape) sees (i2d_world_cast_mover). */
  castMover(capsule, translation, filter) { return castMover(this, capsule, translation, filter); }

  /** The planes of the shapes within the contact slop of the capsule (i2d_world_collide_mover),
   *  each {normal (from the shape toward the capsule), offset (the separation), pushLimit,
   *  push, clipVelocity}: what Impulse2d.solvePlanes and clipVector take. */
  collideMover(capsule, filter) { return collideMover(this, capsule, filter); }

  /**
   * Draws the world through the drawer's methods (i2d_world_draw), on this thread, before
   * it returns. The drawer has any of drawPolygon(vertices, color), drawSolidPolygon(
   * transform, vertices, radius, color), drawCircle(center, radius, color),
   * drawSolidCircle(transform, radius, color), drawSolidCapsule(p1, p2, radius, color),
   * drawSegment(p1, p2, color), drawTransform(transform), drawPoint(p, size, color),
   * drawString(p, text, color); kinds it lacks are not drawn. Vertices are a Float32Array
   * of x, y pairs viewing the module's memory, valid during the call (slice() to keep);
   * colours are 0xRRGGBB (DRAW_COLORS, colorToCss). Options: the flags drawShapes and
   * drawJoints (default true), drawJointExtras, drawBounds, drawMass, drawContacts,
   * drawContactNormals, drawContactImpulses, drawFrictionImpulses, drawGraphColors,
   * drawIslands (default false), and drawingBounds {minX, minY, maxX, maxY} to cull to.
   * The world is locked meanwhile (getters and queries work). The first error a method
   * throws ends the drawing and is thrown once the library has returned.
   */
  draw(drawer, options) { drawWorld(this, drawer, options); }

  get gravity() {
    const rt = this.rt;
    rt.m._i2d_world_get_gravity(rt.result(), this.id);
    rt.checkLast();
    return rt.readVec2(rt.result());
  }
  set gravity(g) {
    this.rt.check(this.rt.m._i2d_world_set_gravity(this.id, this.rt.vec2(0, vx(g), vy(g))));
  }

  /**
   * The world's settings as its def holds them (i2d_world_get_settings): what the
   * setters below last gave, the rest as created. Lengths in the world's units.
   */
  settings() {
    const rt = this.rt;
    const at = rt.result();
    rt.m._i2d_world_get_settings(at, this.id);
    rt.checkLast();
    return readWorldDef(rt, at);
  }

  /** Turning sleep off wakes every body. */
  enableSleeping(flag) { this.rt.check(this.rt.m._i2d_world_enable_sleeping(this.id, flag ? 1 : 0)); }
  enableContinuous(flag) { this.rt.check(this.rt.m._i2d_world_enable_continuous(this.id, flag ? 1 : 0)); }
  enableImpactChains(flag) { this.rt.check(this.rt.m._i2d_world_enable_impact_chains(this.id, flag ? 1 : 0)); }
  setContactTuning(hertz, dampingRatio, pushMaxSpeed) {
    this.rt.check(this.rt.m._i2d_world_set_contact_tuning(this.id, hertz, dampingRatio, pushMaxSpeed));
  }
  setJointTuning(hertz, dampingRatio) {
    this.rt.check(this.rt.m._i2d_world_set_joint_tuning(this.id, hertz, dampingRatio));
  }
  setRestitutionThreshold(speed) { this.rt.check(this.rt.m._i2d_world_set_restitution_threshold(this.id, speed)); }
  setHitEventThreshold(speed) { this.rt.check(this.rt.m._i2d_world_set_hit_event_threshold(this.id, speed)); }

  /** Moves the origin to newOrigin (present coordinates): every position the world keeps
   *  or reports is relative to it afterwards (i2d_world_shift_origin). */
  shiftOrigin(newOrigin) {
    const rt = this.rt;
    rt.check(rt.m._i2d_world_shift_origin(this.id, rt.vec2(0, vx(newOrigin), vy(newOrigin))));
  }

  createBody(options = {}) {
    const rt = this.rt;
    const index = this.freeIndices.length > 0 ? this.freeIndices.pop() : this.bodyByIndex.length;
    const def = rt.defBlock('body');
    try {
      writeBodyDef(rt, def, options, index);
      const body = new Body(this, rt.checkId(rt.m._i2d_body_create(this.id, def)), index);
      this.bodyByIndex[index] = body;
      return body;
    } catch (error) {
      if (index !== this.bodyByIndex.length) this.freeIndices.push(index);
      throw error;
    } finally {
      rt.m._free(def);
    }
  }

  /** Live bodies, in creation order of their indices. */
  get bodies() { return this.bodyByIndex.filter((b) => b !== undefined); }

  // Joints between bodyA and bodyB of this world (at least one dynamic); options are the
  // kind's settings as its class names them (include/impulse2d/joint.h documents each).
  createRevoluteJoint(bodyA, bodyB, options) { return this.makeJoint('revolute', bodyA, bodyB, options); }
  createPrismaticJoint(bodyA, bodyB, options) { return this.makeJoint('prismatic', bodyA, bodyB, options); }
  createDistanceJoint(bodyA, bodyB, options) { return this.makeJoint('distance', bodyA, bodyB, options); }
  createWeldJoint(bodyA, bodyB, options) { return this.makeJoint('weld', bodyA, bodyB, options); }
  createWheelJoint(bodyA, bodyB, options) { return this.makeJoint('wheel', bodyA, bodyB, options); }
  createMotorJoint(bodyA, bodyB, options) { return this.makeJoint('motor', bodyA, bodyB, options); }
  /** bodyA is not moved (any body of the world, often a static one); bodyB must be dynamic. */
  createMouseJoint(bodyA, bodyB, options) { return this.makeJoint('mouse', bodyA, bodyB, options); }
  createFilterJoint(bodyA, bodyB, options) { return this.makeJoint('filter', bodyA, bodyB, options); }

  /** Live joints, in creation order. */
  get joints() { return [...this.jointById.values()]; }

  /** Joints alive in the world, as the library counts them. */
  jointCount() {
    const count = this.rt.m._i2d_world_get_joint_count(this.id);
    this.rt.checkLast();
    return count;
  }

  /** Joints whose reaction force or torque passed its threshold in the last step. */
  jointEvents() {
    const rt = this.rt;
    const at = rt.result();
    rt.m._i2d_world_get_joint_events(at, this.id);
    rt.checkLast();
    const events = rt.u32[(at + rt.field('i2d_joint_events.events')) >> 2];
    const count = rt.i32[(at + rt.field('i2d_joint_events.count')) >> 2];
    const stride = rt.size('i2d_joint_event');
    const idOffset = rt.field('i2d_joint_event.joint');
    const joints = [];
    for (let i = 0; i < count; i++) {
      const id = rt.u64[(events + i * stride + idOffset) >> 3];
      joints.push(this.jointById.get(id) ?? id);
    }
    return joints;
  }

  /** {bodyCount, shapeCount, contactCount, awakeBodyCount}. */
  counters() {
    const rt = this.rt;
    const at = rt.result();
    rt.m._i2d_world_get_counters(at, this.id);
    rt.checkLast();
    const i = rt.i32;
    const read = (name) => i[(at + rt.field(`i2d_world_counters.${name}`)) >> 2];
    return { bodyCount: read('body_count'), shapeCount: read('shape_count'),
             contactCount: read('contact_count'), awakeBodyCount: read('awake_body_count') };
  }

  /** 64-bit hash of every body's state: equal hashes mean equal states. */
  stateHash() {
    const hash = this.rt.m._i2d_world_get_state_hash(this.id);
    this.rt.checkLast();
    return BigInt.asUintN(64, hash);
  }

  /** The SIMD path solving contacts, as i2d_simd_path numbers it: 6 (wasm128) in the SIMD
   *  build unless the world asked for 'scalar', 1 in the scalar build. SIMD_PATH_NAMES[path]
   *  names it. */
  simdPath() { return this.rt.m._i2d_world_get_simd_path(this.id); }

  /**
   * Every body that moved in the last step, read straight from the world's event array
   * (no copy). Valid until the next step or any call that may grow the module's memory.
   */
  bodyMoves() {
    const rt = this.rt;
    const at = rt.result();
    rt.m._i2d_world_get_body_events(at, this.id);
    rt.checkLast();
    const events = rt.u32[(at + rt.field('i2d_body_events.move_events')) >> 2];
    const count = rt.i32[(at + rt.field('i2d_body_events.move_count')) >> 2];
    return new BodyMoves(this, events, count);
  }

  /** Contacts begun and ended in the last step: {begin: [[Shape, Shape]], end: [...]}. */
  contactEvents() {
    const rt = this.rt;
    const at = rt.result();
    rt.m._i2d_world_get_contact_events(at, this.id);
    rt.checkLast();
    const word = (name) => rt.u32[(at + rt.field(`i2d_contact_events.${name}`)) >> 2];
    // Each event holds its two ids (8-byte aligned); begin events carry a manifold too.
    const pairs = (array, count, type) => {
      const stride = rt.size(type) / 8;
      const first = rt.field(`${type}.shape_a`) / 8, second = rt.field(`${type}.shape_b`) / 8;
      const ids = new BigUint64Array(rt.u8.buffer, array, count * stride);
      const out = [];
      for (let i = 0; i < count; i++) {
        const a = ids[stride * i + first], b = ids[stride * i + second];
        out.push([this.shapeById.get(a) ?? a, this.shapeById.get(b) ?? b]);
      }
      return out;
    };
    return {
      begin: pairs(word('begin_events'), word('begin_count'), 'i2d_contact_begin_event'),
      end: pairs(word('end_events'), word('end_count'), 'i2d_contact_end_event'),
    };
  }

  /** Shapes whose geometry overlaps the box, every category. */
  overlapAABB(minX, minY, maxX, maxY) {
    const rt = this.rt;
    const box = rt.arg(0);
    rt.writeVec2(box + rt.field('i2d_aabb.min'), minX, minY);
    rt.writeVec2(box + rt.field('i2d_aabb.max'), maxX, maxY);
    let capacity = 64;
    for (;;) {
      const out = rt.m._malloc(capacity * 8);
      try {
        const total = rt.m._i2d_world_overlap_aabb_ids(this.id, box, rt.allFilter, out, capacity);
        if (total < 0) throw rt.lastError();
        if (total <= capacity) {
          return Array.from(new BigUint64Array(rt.u8.buffer, out, total), (id) => this.shapeById.get(id));
        }
        capacity = total;
      } finally {
        rt.m._free(out);
      }
    }
  }

  /** The first shape along origin + t translation, t in [0, 1]: {shape, point, normal, fraction} or null. */
  castRayClosest(origin, translation) {
    const rt = this.rt;
    const at = rt.result();
    rt.m._i2d_world_cast_ray_closest(at, this.id, rt.vec2(0, vx(origin), vy(origin)),
                                     rt.vec2(1, vx(translation), vy(translation)), rt.allFilter);
    rt.checkLast();
    if (rt.u8[at + rt.field('i2d_ray_result.hit')] === 0) return null;
    const id = rt.u64[(at + rt.field('i2d_ray_result.shape')) >> 3];
    return {
      shape: this.shapeById.get(id),
      point: rt.readVec2(at + rt.field('i2d_ray_result.point')),
      normal: rt.readVec2(at + rt.field('i2d_ray_result.normal')),
      fraction: rt.f32[(at + rt.field('i2d_ray_result.fraction')) >> 2],
    };
  }

  /** Destroys the world and everything in it. */
  destroy() {
    if (this.owner !== null) throw new Error(`this world belongs to its ${this.owner}: close that instead`);
    this.rt.check(this.rt.m._i2d_world_destroy(this.id));
    this.rt.threadsLent -= this.threads;
    this.threads = 0;
    this.hooks.release();
    this.recorder?.release();
    this.recorder = null;
    this.bodyByIndex = [undefined];
    this.freeIndices = [];
    this.shapeById.clear();
    this.jointById.clear();
  }

  /**
   * @internal The entries of i2d_body_get_contact_data or i2d_shape_get_contact_data:
   * [{shapeA, shapeB, normal, points: [{point, penetration, id, normalImpulse, tangentImpulse}]}].
   */
  contactData(fn, id) {
    const rt = this.rt;
    const stride = rt.size('i2d_contact_data');
    const field = (name) => rt.field(`i2d_contact_data.${name}`);
    const read = (out, count) => {
      const entries = [];
      for (let i = 0; i < count; i++) {
        const at = out + i * stride;
        const shape = (name) => {
          const shapeId = rt.u64[(at + field(name)) >> 3];
          return this.shapeById.get(shapeId) ?? shapeId;
        };
        const { normal, points } = readManifold(rt, at + field('manifold'));
        points.forEach((p, j) => {
          p.normalImpulse = rt.f32[((at + field('normal_impulses')) >> 2) + j];
          p.tangentImpulse = rt.f32[((at + field('tangent_impulses')) >> 2) + j];
        });
        entries.push({ shapeA: shape('shape_a'), shapeB: shape('shape_b'), normal, points });
      }
      return entries;
    };
    return rt.filled(stride, (out, capacity) => rt.m[fn](id, out, capacity), read);
  }

  /** @internal */
  rememberShape(shape) { this.shapeById.set(shape.id, shape); }
  /** @internal */
  makeJoint(kind, bodyA, bodyB, options) {
    const joint = createJoint(this, kind, bodyA, bodyB, options);
    this.jointById.set(joint.id, joint);
    bodyA.joints.push(joint);
    bodyB.joints.push(joint);
    return joint;
  }
  /** @internal */
  forgetJoint(joint) {
    this.jointById.delete(joint.id);
    for (const body of [joint.bodyA, joint.bodyB]) body.joints.splice(body.joints.indexOf(joint), 1);
  }
  /** @internal */
  forgetShape(shape) {
    this.shapeById.delete(shape.id);
    const list = shape.body.shapes;
    list.splice(list.indexOf(shape), 1);
  }
  /**
   * @internal After a restore: the objects the world had when `structure` was recorded,
   * this world's own or, for another world's record, new ones over the translated ids.
   */
  adoptStructure(structure) {
    const rt = this.rt;
    const own = structure.world === this;
    // An id of the recorded world as an id of this one, if it names something here.
    const translate = (kind, id) => {
      const there = own ? id : rt.m[`_i2d_${kind}_in_world`](id, this.id);
      return rt.m[`_i2d_${kind}_is_valid`](there) !== 0 ? there : undefined;
    };
    const bodyFor = new Map();
    this.bodyByIndex = [undefined];
    this.shapeById.clear();
    this.jointById.clear();
    for (const [old, shapes] of structure.bodies) {
      const id = translate('body', old.id);
      if (id === undefined) continue;
      const body = own ? old : Object.assign(new Body(this, id, old.index), { userData: old.userData });
      body.shapes.length = 0;
      body.joints.length = 0;
      for (const oldShape of shapes) {
        const shapeId = translate('shape', oldShape.id);
        if (shapeId === undefined) continue;
        const shape = own ? oldShape : Object.assign(new Shape(body, shapeId), { userData: oldShape.userData });
        body.shapes.push(shape);
        this.shapeById.set(shape.id, shape);
      }
      this.bodyByIndex[body.index] = body;
      bodyFor.set(old, body);
    }
    for (const old of structure.joints) {
      const id = translate('joint', old.id);
      const bodyA = bodyFor.get(old.bodyA), bodyB = bodyFor.get(old.bodyB);
      if (id === undefined || bodyA === undefined || bodyB === undefined) continue;
      const joint = own ? old : Object.assign(new old.constructor(this, id, bodyA, bodyB), { userData: old.userData });
      this.jointById.set(joint.id, joint);
      bodyA.joints.push(joint);
      bodyB.joints.push(joint);
    }
    this.freeIndices = [];
    for (let index = this.bodyByIndex.length - 1; index > 0; index--) {
      if (this.bodyByIndex[index] === undefined) this.freeIndices.push(index);
    }
  }

  /** @internal After a restore of bytes without a record: drops the objects made since the save. */
  forgetStale() {
    for (const joint of this.joints) if (!joint.isValid()) this.forgetJoint(joint);
    for (const body of this.bodies) {
      if (!body.isValid()) {
        this.forgetBody(body);
        continue;
      }
      for (const shape of [...body.shapes]) if (!shape.isValid()) this.forgetShape(shape);
    }
  }

  /** @internal The library destroyed the body's joints with it. */
  forgetBody(body) {
    for (const joint of [...body.joints]) this.forgetJoint(joint);
    for (const shape of body.shapes) this.shapeById.delete(shape.id);
    this.bodyByIndex[body.index] = undefined;
    this.freeIndices.push(body.index);
  }
}

/**
 * The worker threads a world of `workerCount` workers takes from the build's pool. The
 * threads build starts its workers with the module, since a page cannot start one while a
 * step waits for it: a world asking for more than are free would wait forever, so it is
 * refused here.
 */
function threadsFor(rt, workerCount = 1) {
  if (!Number.isInteger(workerCount) || workerCount < 1) {
    throw new TypeError(`workerCount is ${String(workerCount)}; it must be a whole number from 1`);
  }
  const threads = workerCount - 1;
  if (threads > rt.threadPoolSize - rt.threadsLent) {
    throw new RangeError(rt.threadPoolSize === 0
      ? `workerCount ${workerCount}: this build has no threads; loadImpulse2d({ threads: true }) loads the one ` +
        'that has (node, or a cross-origin isolated page)'
      : `workerCount ${workerCount}: ${rt.threadPoolSize - rt.threadsLent} of the build's ${rt.threadPoolSize} ` +
        'worker threads are free (the worlds alive hold the rest); destroy one first');
  }
  return threads;
}

function writeWorldDef(rt, def, options) {
  const f = rt.f32;
  if (options.gravity !== undefined) {
    f[(def + rt.field('i2d_world_def.gravity')) >> 2] = vx(options.gravity);
    f[((def + rt.field('i2d_world_def.gravity')) >> 2) + 1] = vy(options.gravity);
  }
  if (options.contactHertz !== undefined) f[(def + rt.field('i2d_world_def.contact_hertz')) >> 2] = options.contactHertz;
  if (options.restitutionThreshold !== undefined) {
    f[(def + rt.field('i2d_world_def.restitution_threshold')) >> 2] = options.restitutionThreshold;
  }
  if (options.enableSleep !== undefined) rt.u8[def + rt.field('i2d_world_def.enable_sleep')] = options.enableSleep ? 1 : 0;
  if (options.simdPath !== undefined) {
    const path = typeof options.simdPath === 'string' ? SIMD_PATH_NAMES.indexOf(options.simdPath) : options.simdPath;
    if (!Number.isInteger(path) || path < 0) {
      throw new TypeError(`simdPath is ${String(options.simdPath)}; it must be one of ${SIMD_PATH_NAMES.join(', ')}`);
    }
    rt.i32[(def + rt.field('i2d_world_def.simd_path')) >> 2] = path;
  }
}

/** @internal An i2d_world_def at `at` as the settings object World.settings gives. */
export function readWorldDef(rt, at) {
  const field = (name) => at + rt.field(`i2d_world_def.${name}`);
  const float = (name) => rt.f32[field(name) >> 2];
  const flag = (name) => rt.u8[field(name)] !== 0;
  return {
    gravity: rt.readVec2(field('gravity')),
    contactSlop: float('contact_slop'),
    contactHertz: float('contact_hertz'),
    contactDampingRatio: float('contact_damping_ratio'),
    contactPushMaxSpeed: float('contact_push_max_speed'),
    restitutionThreshold: float('restitution_threshold'),
    maximumLinearSpeed: float('maximum_linear_speed'),
    enableSleep: flag('enable_sleep'),
    sleepSpeedThreshold: float('sleep_speed_threshold'),
    timeToSleep: float('time_to_sleep'),
    enableContactRecycling: flag('enable_contact_recycling'),
    jointHertz: float('joint_hertz'),
    jointDampingRatio: float('joint_damping_ratio'),
    enableContinuous: flag('enable_continuous'),
    enableImpactChains: flag('enable_impact_chains'),
    hitEventThreshold: float('hit_event_threshold'),
    lengthUnitsPerMeter: float('length_units_per_meter'),
    simdPath: SIMD_PATH_NAMES[rt.i32[field('simd_path') >> 2]],
  };
}

const EXPLOSION_SETTINGS = ['position', 'radius', 'falloff', 'impulsePerLength', 'maskBits'];

function writeExplosionDef(rt, def, options) {
  for (const name of Object.keys(options)) {
    if (!EXPLOSION_SETTINGS.includes(name)) {
      throw new TypeError(`an explosion has no setting '${name}'; known: ${EXPLOSION_SETTINGS.join(', ')}`);
    }
  }
  const field = (name) => def + rt.field(`i2d_explosion_def.${name}`);
  // Always written: a missing position reads as NaN, which the library refuses.
  rt.writeVec2(field('position'), vx(options.position), vy(options.position));
  if (options.radius !== undefined) rt.f32[field('radius') >> 2] = options.radius;
  if (options.falloff !== undefined) rt.f32[field('falloff') >> 2] = options.falloff;
  if (options.impulsePerLength !== undefined) rt.f32[field('impulse_per_length') >> 2] = options.impulsePerLength;
  if (options.maskBits !== undefined) rt.u64[field('mask_bits') >> 3] = BigInt.asUintN(64, BigInt(options.maskBits));
}

function writeBodyDef(rt, def, options, index) {
  const f = rt.f32;
  const field = (name) => def + rt.field(`i2d_body_def.${name}`);
  if (options.type !== undefined) {
    rt.i32[field('type') >> 2] = typeof options.type === 'number' ? options.type : (BODY_TYPES[options.type] ?? -1);
  }
  const pair = (name, v) => {
    f[field(name) >> 2] = vx(v);
    f[(field(name) >> 2) + 1] = vy(v);
  };
  if (options.position !== undefined) pair('position', options.position);
  if (options.angle !== undefined) pair('rotation', [Math.cos(options.angle), Math.sin(options.angle)]);
  if (options.linearVelocity !== undefined) pair('linear_velocity', options.linearVelocity);
  if (options.angularVelocity !== undefined) f[field('angular_velocity') >> 2] = options.angularVelocity;
  if (options.linearDamping !== undefined) f[field('linear_damping') >> 2] = options.linearDamping;
  if (options.angularDamping !== undefined) f[field('angular_damping') >> 2] = options.angularDamping;
  if (options.gravityScale !== undefined) f[field('gravity_scale') >> 2] = options.gravityScale;
  if (options.fixedRotation !== undefined) rt.u8[field('fixed_rotation')] = options.fixedRotation ? 1 : 0;
  if (options.enableSleep !== undefined) rt.u8[field('enable_sleep')] = options.enableSleep ? 1 : 0;
  rt.u32[field('user_data') >> 2] = index;
}
