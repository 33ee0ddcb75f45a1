// SPDX-License-Identifier: MIT
// A rigid body: a thin handle over an i2d_body_id, and the factory of its shapes.
import { writeFilter } from './filters.js';
import { Shape } from './shape.js';
import { vx, vy } from './vectors.js';

export const BODY_TYPES = { static: 0, kinematic: 1, dynamic: 2 };
const BODY_TYPE_NAMES = ['static', 'kinematic', 'dynamic'];

export class Body {
  /** @internal Made by World.createBody. */
  constructor(world, id, index) {
    this.world = world;
    this.id = id;
    /** The body's number in its world: the user data that move events carry. */
    this.index = index;
    /** Free for the caller's own use. */
    this.userData = undefined;
    /** @type {Shape[]} */
    this.shapes = [];
    /** Joints this body is one of the two bodies of. */
    this.joints = [];
  }

  get rt() { return this.world.rt; }

  isValid() { return this.rt.m._i2d_body_is_valid(this.id) !== 0; }

  get type() { return BODY_TYPE_NAMES[this.getter('_i2d_body_get_type')]; }

  get position() { return this.vec2Getter('_i2d_body_get_position'); }
  /** Radians, counter-clockwise. */
  get angle() {
    const rt = this.rt;
    rt.m._i2d_body_get_rotation(rt.result(), this.id);
    rt.checkLast();
    const r = rt.readVec2(rt.result());
    return Math.atan2(r.y, r.x);
  }
  /** {x, y, c, s}: origin and rotation (cosine, sine). */
  transform() {
    const rt = this.rt;
    rt.m._i2d_body_get_transform(rt.result(), this.id);
    rt.checkLast();
    const f = rt.f32;
    const at = rt.result() >> 2;
    return { x: f[at], y: f[at + 1], c: f[at + 2], s: f[at + 3] };
  }
  setTransform(position, angle = this.angle) {
    const rt = this.rt;
    rt.check(rt.m._i2d_body_set_transform(this.id, rt.vec2(0, vx(position), vy(position)), rt.rot(1, angle)));
  }

  /** A world point in the body's frame: how joint anchors are given. */
  getLocalPoint(worldPoint) {
    const rt = this.rt;
    rt.m._i2d_body_get_local_point(rt.result(), this.id, rt.vec2(0, vx(worldPoint), vy(worldPoint)));
    rt.checkLast();
    return rt.readVec2(rt.result());
  }
  /** A point of the body's frame in the world. */
  getWorldPoint(localPoint) {
    const rt = this.rt;
    rt.m._i2d_body_get_world_point(rt.result(), this.id, rt.vec2(0, vx(localPoint), vy(localPoint)));
    rt.checkLast();
    return rt.readVec2(rt.result());
  }

  get linearVelocity() { return this.vec2Getter('_i2d_body_get_linear_velocity'); }
  set linearVelocity(v) { this.setLinearVelocity(v); }
  setLinearVelocity(v) {
    const rt = this.rt;
    rt.check(rt.m._i2d_body_set_linear_velocity(this.id, rt.vec2(0, vx(v), vy(v))));
  }
  get angularVelocity() { return this.getter('_i2d_body_get_angular_velocity'); }
  set angularVelocity(w) { this.rt.check(this.rt.m._i2d_body_set_angular_velocity(this.id, w)); }

  get mass() { return this.getter('_i2d_body_get_mass'); }
  get worldCenterOfMass() { return this.vec2Getter('_i2d_body_get_world_center_of_mass'); }
  get awake() { return this.getter('_i2d_body_is_awake') !== 0; }
  set awake(awake) { this.rt.check(this.rt.m._i2d_body_set_awake(this.id, awake ? 1 : 0)); }
  /** True after a step froze the body because its state went non-finite (see the C header). */
  get quarantined() { return this.getter('_i2d_body_is_quarantined') !== 0; }

  applyLinearImpulse(impulse, point = this.worldCenterOfMass, wake = true) {
    const rt = this.rt;
    rt.check(rt.m._i2d_body_apply_linear_impulse(this.id, rt.vec2(0, vx(impulse), vy(impulse)),
                                                  rt.vec2(1, vx(point), vy(point)), wake ? 1 : 0));
  }
  applyForceToCenter(force, wake = true) {
    const rt = this.rt;
    rt.check(rt.m._i2d_body_apply_force_to_center(this.id, rt.vec2(0, vx(force), vy(force)), wake ? 1 : 0));
  }

  /** {mass, center, rotationalInertia}: kg, the centre of mass in the body frame, kg m^2 about it. */
  get massData() {
    const rt = this.rt;
    const at = rt.result();
    rt.m._i2d_body_get_mass_data(at, this.id);
    rt.checkLast();
    return {
      mass: rt.f32[(at + rt.field('i2d_mass_data.mass')) >> 2],
      center: rt.readVec2(at + rt.field('i2d_mass_data.center')),
      rotationalInertia: rt.f32[(at + rt.field('i2d_mass_data.rotational_inertia')) >> 2],
    };
  }
  set massData(data) { this.setMassData(data); }
  /** Overrides the mass the shapes give a dynamic body, until applyMassFromShapes. */
  setMassData({ mass, center = [0, 0], rotationalInertia } = {}) {
    const rt = this.rt;
    const at = rt.arg(0);
    rt.f32[(at + rt.field('i2d_mass_data.mass')) >> 2] = Number(mass);
    rt.writeVec2(at + rt.field('i2d_mass_data.center'), vx(center), vy(center));
    rt.f32[(at + rt.field('i2d_mass_data.rotational_inertia')) >> 2] = Number(rotationalInertia);
    rt.check(rt.m._i2d_body_set_mass_data(this.id, at));
  }
  /** Drops a setMassData override: the mass comes from the shapes' densities again. */
  applyMassFromShapes() { this.rt.check(this.rt.m._i2d_body_apply_mass_from_shapes(this.id)); }

  /** Takes the body out of the world (i2d_body_disable): no contacts, queries or joints. */
  disable() { this.rt.check(this.rt.m._i2d_body_disable(this.id)); }
  /** Brings a disabled body back where it stands, awake. */
  enable() { this.rt.check(this.rt.m._i2d_body_enable(this.id)); }
  get enabled() { return this.getter('_i2d_body_is_enabled') !== 0; }
  set enabled(flag) { if (flag) this.enable(); else this.disable(); }

  /** Sets a kinematic body's velocities so that it reaches the pose in timeStep seconds. */
  setTargetTransform(position, angle, timeStep) {
    const rt = this.rt;
    rt.check(rt.m._i2d_body_set_target_transform(this.id, rt.transform(0, position, angle), timeStep));
  }

  get bullet() { return this.getter('_i2d_body_is_bullet') !== 0; }
  set bullet(flag) { this.rt.check(this.rt.m._i2d_body_set_bullet(this.id, flag ? 1 : 0)); }
  /** False keeps the body (and what touches it) awake. */
  get sleepEnabled() { return this.getter('_i2d_body_is_sleep_enabled') !== 0; }
  set sleepEnabled(flag) { this.rt.check(this.rt.m._i2d_body_enable_sleep(this.id, flag ? 1 : 0)); }
  /** The speed below which the body counts as resting, world length units per second. */
  get sleepThreshold() { return this.getter('_i2d_body_get_sleep_threshold'); }
  set sleepThreshold(speed) { this.rt.check(this.rt.m._i2d_body_set_sleep_threshold(this.id, speed)); }
  get gravityScale() { return this.getter('_i2d_body_get_gravity_scale'); }
  set gravityScale(scale) { this.rt.check(this.rt.m._i2d_body_set_gravity_scale(this.id, scale)); }
  get linearDamping() { return this.getter('_i2d_body_get_linear_damping'); }
  set linearDamping(damping) { this.rt.check(this.rt.m._i2d_body_set_linear_damping(this.id, damping)); }
  get angularDamping() { return this.getter('_i2d_body_get_angular_damping'); }
  set angularDamping(damping) { this.rt.check(this.rt.m._i2d_body_set_angular_damping(this.id, damping)); }
  get fixedRotation() { return this.getter('_i2d_body_is_fixed_rotation') !== 0; }
  set fixedRotation(flag) { this.rt.check(this.rt.m._i2d_body_set_fixed_rotation(this.id, flag ? 1 : 0)); }

  /** The body's touching contacts as the last step left them (see World.readContactData). */
  contactData() { return this.world.contactData('_i2d_body_get_contact_data', this.id); }

  /** A box centred on the body origin, axis-aligned in the body frame. */
  createBox(halfWidth, halfHeight, options) {
    return this.makeShape(options, (def) => this.rt.m._i2d_shape_create_box(this.id, def, halfWidth, halfHeight));
  }
  /** A box centred at `center` (body frame), turned by `angle` radians there. */
  createOffsetBox(halfWidth, halfHeight, center, angle = 0, options) {
    const rt = this.rt;
    return this.makeShape(options, (def) => rt.m._i2d_shape_create_offset_box(
      this.id, def, halfWidth, halfHeight, rt.vec2(0, vx(center), vy(center)), rt.rot(1, angle)));
  }
  createCircle(radius, options = {}) {
    const rt = this.rt;
    const center = options.center ?? [0, 0];
    return this.makeShape(options, (def) => {
      const circle = rt.arg(0);
      rt.writeVec2(circle + rt.field('i2d_circle.center'), vx(center), vy(center));
      rt.f32[(circle + rt.field('i2d_circle.radius')) >> 2] = radius;
      return rt.m._i2d_shape_create_circle(this.id, def, circle);
    });
  }
  /** The convex hull of 3 to 8 points (body frame). */
  createPolygon(points, options) {
    const rt = this.rt;
    if (!Array.isArray(points) || points.length > 8) {
      return this.makeShape(options, (def) => rt.m._i2d_shape_create_polygon(this.id, def, rt.arg(0),
                                                                              Array.isArray(points) ? points.length : 0));
    }
    return this.makeShape(options, (def) => {
      const at = rt.arg(0);  // 8 points fill exactly one 64-byte argument slot
      points.forEach((p, i) => {
        rt.f32[(at >> 2) + 2 * i] = vx(p);
        rt.f32[(at >> 2) + 2 * i + 1] = vy(p);
      });
      return rt.m._i2d_shape_create_polygon(this.id, def, at, points.length);
    });
  }
  createCapsule(center1, center2, radius, options) {
    const rt = this.rt;
    return this.makeShape(options, (def) => rt.m._i2d_shape_create_capsule(
      this.id, def, rt.vec2(0, vx(center1), vy(center1)), rt.vec2(1, vx(center2), vy(center2)), radius));
  }
  createSegment(point1, point2, options) {
    const rt = this.rt;
    return this.makeShape(options, (def) => rt.m._i2d_shape_create_segment(
      this.id, def, rt.vec2(0, vx(point1), vy(point1)), rt.vec2(1, vx(point2), vy(point2))));
  }

  /** Destroys the body, its shapes and its joints. */
  destroy() {
    this.rt.check(this.rt.m._i2d_body_destroy(this.id));
    this.world.forgetBody(this);
  }

  makeShape(options = {}, create) {
    const rt = this.rt;
    const def = rt.defBlock('shape');
    try {
      writeShapeDef(rt, def, options);
      const shape = new Shape(this, rt.checkId(create(def)));
      this.shapes.push(shape);
      this.world.rememberShape(shape);
      return shape;
    } finally {
      rt.m._free(def);
    }
  }

  getter(fn) {
    const value = this.rt.m[fn](this.id);
    this.rt.checkLast();
    return value;
  }

  vec2Getter(fn) {
    const rt = this.rt;
    rt.m[fn](rt.result(), this.id);
    rt.checkLast();
    return rt.readVec2(rt.result());
  }
}

function writeShapeDef(rt, def, options) {
  const f = rt.f32;
  const u8 = rt.u8;
  if (options.density !== undefined) f[(def + rt.field('i2d_shape_def.density')) >> 2] = options.density;
  if (options.friction !== undefined) f[(def + rt.field('i2d_shape_def.friction')) >> 2] = options.friction;
  if (options.restitution !== undefined) f[(def + rt.field('i2d_shape_def.restitution')) >> 2] = options.restitution;
  if (options.isSensor !== undefined) u8[def + rt.field('i2d_shape_def.is_sensor')] = options.isSensor ? 1 : 0;
  if (options.enableContactEvents !== undefined) {
    u8[def + rt.field('i2d_shape_def.enable_contact_events')] = options.enableContactEvents ? 1 : 0;
  }
  // The contact hooks' opt-ins (World.setCustomFilter, World.setPreSolve).
  if (options.enableCustomFiltering !== undefined) {
    u8[def + rt.field('i2d_shape_def.enable_custom_filtering')] = options.enableCustomFiltering ? 1 : 0;
  }
  if (options.enablePreSolveEvents !== undefined) {
    u8[def + rt.field('i2d_shape_def.enable_pre_solve_events')] = options.enablePreSolveEvents ? 1 : 0;
  }
  // Which shapes it collides with ({categoryBits, maskBits, groupIndex}), and which
  // queries and character moves see it (their filter's mask against its category).
  if (options.filter !== undefined) writeFilter(rt, def + rt.field('i2d_shape_def.filter'), options.filter);
}
