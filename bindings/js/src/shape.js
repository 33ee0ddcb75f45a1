// SPDX-License-Identifier: MIT
// A shape on a body: a thin handle over an i2d_shape_id.
import { vx, vy } from './vectors.js';

const SHAPE_TYPES = ['circle', 'capsule', 'segment', 'polygon'];

export class Shape {
  /** @internal Made by Body's create* methods. */
  constructor(body, id) {
    this.body = body;
    this.id = id;
    /** Free for the caller's own use. */
    this.userData = undefined;
  }

  get rt() { return this.body.world.rt; }

  isValid() { return this.rt.m._i2d_shape_is_valid(this.id) !== 0; }

  get type() {
    const type = this.rt.m._i2d_shape_get_type(this.id);
    this.rt.checkLast();
    return SHAPE_TYPES[type];
  }

  /** Tight world-space bounds: {minX, minY, maxX, maxY}. */
  aabb() {
    const rt = this.rt;
    rt.m._i2d_shape_get_aabb(rt.result(), this.id);
    rt.checkLast();
    const f = rt.f32;
    const at = rt.result() >> 2;
    return { minX: f[at], minY: f[at + 1], maxX: f[at + 2], maxY: f[at + 3] };
  }

  get friction() { return this.getter('_i2d_shape_get_friction'); }
  set friction(value) { this.rt.check(this.rt.m._i2d_shape_set_friction(this.id, value)); }
  get restitution() { return this.getter('_i2d_shape_get_restitution'); }
  set restitution(value) { this.rt.check(this.rt.m._i2d_shape_set_restitution(this.id, value)); }
  get density() { return this.getter('_i2d_shape_get_density'); }
  set density(value) { this.setDensity(value); }
  /** kg/m^2; updateBodyMass false leaves the body's mass until the next shape change. */
  setDensity(density, updateBodyMass = true) {
    this.rt.check(this.rt.m._i2d_shape_set_density(this.id, density, updateBodyMass ? 1 : 0));
  }

  /** {friction, restitution, rollingResistance, tangentSpeed}. */
  get material() {
    const rt = this.rt;
    const at = rt.result();
    rt.m._i2d_shape_get_material(at, this.id);
    rt.checkLast();
    const read = (name) => rt.f32[(at + rt.field(`i2d_surface_material.${name}`)) >> 2];
    return { friction: read('friction'), restitution: read('restitution'),
             rollingResistance: read('rolling_resistance'), tangentSpeed: read('tangent_speed') };
  }
  /** All four at once; a missing one reads as NaN, which the library refuses. */
  set material(material) {
    const rt = this.rt;
    const at = rt.arg(0);
    const write = (name, value) => { rt.f32[(at + rt.field(`i2d_surface_material.${name}`)) >> 2] = Number(value); };
    write('friction', material?.friction);
    write('restitution', material?.restitution);
    write('rolling_resistance', material?.rollingResistance);
    write('tangent_speed', material?.tangentSpeed);
    rt.check(rt.m._i2d_shape_set_material(this.id, at));
  }

  get sensorEventsEnabled() { return this.getter('_i2d_shape_are_sensor_events_enabled') !== 0; }
  set sensorEventsEnabled(flag) { this.rt.check(this.rt.m._i2d_shape_enable_sensor_events(this.id, flag ? 1 : 0)); }
  get contactEventsEnabled() { return this.getter('_i2d_shape_are_contact_events_enabled') !== 0; }
  set contactEventsEnabled(flag) { this.rt.check(this.rt.m._i2d_shape_enable_contact_events(this.id, flag ? 1 : 0)); }
  get hitEventsEnabled() { return this.getter('_i2d_shape_are_hit_events_enabled') !== 0; }
  set hitEventsEnabled(flag) { this.rt.check(this.rt.m._i2d_shape_enable_hit_events(this.id, flag ? 1 : 0)); }
  /** Whether the shape's touching contacts reach World.setPreSolve's hook (from the next step). */
  get preSolveEventsEnabled() { return this.getter('_i2d_shape_are_pre_solve_events_enabled') !== 0; }
  set preSolveEventsEnabled(flag) {
    this.rt.check(this.rt.m._i2d_shape_enable_pre_solve_events(this.id, flag ? 1 : 0));
  }

  // New geometry in the body frame (the kind may change): the body's mass is made again
  // from its shapes and it wakes.
  setCircle(radius, center = [0, 0]) {
    const rt = this.rt;
    const at = rt.arg(0);
    rt.writeVec2(at + rt.field('i2d_circle.center'), vx(center), vy(center));
    rt.f32[(at + rt.field('i2d_circle.radius')) >> 2] = radius;
    rt.check(rt.m._i2d_shape_set_circle(this.id, at));
  }
  setCapsule(center1, center2, radius) {
    const rt = this.rt;
    const at = rt.arg(0);
    rt.writeVec2(at + rt.field('i2d_capsule.center1'), vx(center1), vy(center1));
    rt.writeVec2(at + rt.field('i2d_capsule.center2'), vx(center2), vy(center2));
    rt.f32[(at + rt.field('i2d_capsule.radius')) >> 2] = radius;
    rt.check(rt.m._i2d_shape_set_capsule(this.id, at));
  }
  setSegment(point1, point2) {
    const rt = this.rt;
    const at = rt.arg(0);
    rt.writeVec2(at + rt.field('i2d_segment.point1'), vx(point1), vy(point1));
    rt.writeVec2(at + rt.field('i2d_segment.point2'), vx(point2), vy(point2));
    rt.check(rt.m._i2d_shape_set_segment(this.id, at));
  }
  /** The convex hull of 3 to 8 points (i2d_make_polygon), rounded by radius. */
  setPolygon(points, radius = 0) {
    const rt = this.rt;
    const polygon = rt.result();
    const count = Array.isArray(points) ? points.length : 0;
    const at = rt.arg(0);  // 8 points fill exactly one 64-byte argument slot
    if (count <= 8) {
      points.forEach((p, i) => rt.writeVec2(at + 8 * i, vx(p), vy(p)));
    }
    rt.check(rt.m._i2d_make_polygon(at, count, radius, polygon));
    rt.check(rt.m._i2d_shape_set_polygon(this.id, polygon));
  }

  /** The point of the shape closest to target (world coordinates); target itself inside. */
  closestPoint(target) {
    const rt = this.rt;
    rt.m._i2d_shape_get_closest_point(rt.result(), this.id, rt.vec2(0, vx(target), vy(target)));
    rt.checkLast();
    return rt.readVec2(rt.result());
  }

  /** The shape's touching contacts as the last step left them (as Body.contactData). */
  contactData() { return this.body.world.contactData('_i2d_shape_get_contact_data', this.id); }

  /** The shapes visiting this sensor as of the last step (Shape objects, or ids of shapes
   *  this binding did not make). A shape that is not a sensor is refused. */
  sensorOverlaps() {
    const rt = this.rt;
    const world = this.body.world;
    return rt.filled(8, (out, capacity) => rt.m._i2d_shape_get_sensor_overlaps(this.id, out, capacity),
                     (out, count) => Array.from(new BigUint64Array(rt.u8.buffer, out, count),
                                                (id) => world.shapeById.get(id) ?? id));
  }

  /**
   * The geometry in the body frame, for drawing:
   * {type: 'circle', center, radius} | {type: 'polygon', vertices, radius}
   * | {type: 'capsule', center1, center2, radius} | {type: 'segment', point1, point2}.
   */
  geometry() {
    const rt = this.rt;
    const type = this.type;
    const at = rt.result();
    if (type === 'circle') {
      rt.m._i2d_shape_get_circle(at, this.id);
      rt.checkLast();
      return { type, center: rt.readVec2(at + rt.field('i2d_circle.center')),
               radius: rt.f32[(at + rt.field('i2d_circle.radius')) >> 2] };
    }
    if (type === 'capsule') {
      rt.m._i2d_shape_get_capsule(at, this.id);
      rt.checkLast();
      return { type, center1: rt.readVec2(at + rt.field('i2d_capsule.center1')),
               center2: rt.readVec2(at + rt.field('i2d_capsule.center2')),
               radius: rt.f32[(at + rt.field('i2d_capsule.radius')) >> 2] };
    }
    if (type === 'segment') {
      rt.m._i2d_shape_get_segment(at, this.id);
      rt.checkLast();
      return { type, point1: rt.readVec2(at + rt.field('i2d_segment.point1')),
               point2: rt.readVec2(at + rt.field('i2d_segment.point2')) };
    }
    rt.m._i2d_shape_get_polygon(at, this.id);
    rt.checkLast();
    const count = rt.i32[(at + rt.field('i2d_polygon.count')) >> 2];
    const vertices = [];
    const first = at + rt.field('i2d_polygon.vertices');
    for (let i = 0; i < count; i++) vertices.push(rt.readVec2(first + rt.size('i2d_vec2') * i));
    return { type, vertices, radius: rt.f32[(at + rt.field('i2d_polygon.radius')) >> 2] };
  }

  /** Destroys the shape; its body's mass is updated. */
  destroy() {
    this.rt.check(this.rt.m._i2d_shape_destroy(this.id));
    this.body.world.forgetShape(this);
  }

  getter(fn) {
    const value = this.rt.m[fn](this.id);
    this.rt.checkLast();
    return value;
  }
}
