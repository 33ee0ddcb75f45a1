// SPDX-License-Identifier: MIT
// A world: stepping, bodies, joints, queries and events over an i2d_world_id.
import { Body, BODY_TYPES } from './body.js';
import { BodyMoves } from './body_moves.js';
import { createJoint } from './joint.js';
import { vx, vy } from './vectors.js';

export class World {
  /** @internal Made by Impulse2d.createWorld. */
  constructor(rt, options = {}) {
    this.rt = rt;
    const def = rt.defBlock('world');
    try {
      writeWorldDef(rt, def, options);
      this.id = rt.checkId(rt.m._i2d_world_create(def));
    } finally {
      rt.m._free(def);
    }
    /** Live bodies by index (the user data their move events carry); slot 0 unused. */
    this.bodyByIndex = [undefined];
    this.freeIndices = [];
    this.shapeById = new Map();
    /** Live joints by id, in creation order: what joint events are mapped back through. */
    this.jointById = new Map();
  }

  isValid() { return this.rt.m._i2d_world_is_valid(this.id) !== 0; }

  /** Advances by timeStep seconds in substeps equal substeps. */
  step(timeStep = 1 / 60, substeps = 4) {
    this.rt.check(this.rt.m._i2d_world_step(this.id, timeStep, substeps));
  }

  get gravity() {
    const rt = this.rt;
    rt.m._i2d_world_get_gravity(rt.result(), this.id);
    rt.checkLast();
    return rt.readVec2(rt.result());
  }
  set gravity(g) {
    this.rt.check(this.rt.m._i2d_world_set_gravity(this.id, this.rt.vec2(0, vx(g), vy(g))));
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

  /** The SIMD path solving contacts: 1 (scalar) in WebAssembly. */
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
    this.rt.check(this.rt.m._i2d_world_destroy(this.id));
    this.bodyByIndex = [undefined];
    this.freeIndices = [];
    this.shapeById.clear();
    this.jointById.clear();
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
  /** @internal The library destroyed the body's joints with it. */
  forgetBody(body) {
    for (const joint of [...body.joints]) this.forgetJoint(joint);
    for (const shape of body.shapes) this.shapeById.delete(shape.id);
    this.bodyByIndex[body.index] = undefined;
    this.freeIndices.push(body.index);
  }
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
