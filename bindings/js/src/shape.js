// SPDX-License-Identifier: MIT
// A shape on a body: a thin handle over an i2d_shape_id.

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
